!> The ladder of an accuracy run (docs/ACCURACY.md, how it decides): the time axis (dt0/2^k on
!> mesh 0, runs (k, 0)), the mesh axis (nx, ny times mesh_factor^j at dt0, runs (0, j)) and the
!> runs that combine them. Each axis gives the error of every level: from the last three the
!> observed order p solves (h1^p - h2^p)/(h2^p - h3^p) = d1/d2; in range, Richardson's error at
!> min(p, the method's order) times richardson_safety; monotone but slower, Richardson's at p (at
!> most slow_cap times the larger difference), no less than the safe bound; otherwise the safe
!> bound, safe_factor times the larger difference, never an extrapolation. Two levels:
!> two_level_factor |d| (Roache's GCI, Fs = 3, r^p - 1 taken as 1); one level: huge. A floor is
!> added. The error of a run (k, j) is its time level's plus its mesh level's plus the interaction
!> |q(k,j) - q(k,0) - q(0,j) + q(0,0)|, no less than the largest measured; on a finer mesh its
!> time error is measured there too (time_on_mesh). choose_run: the cheapest run within the
!> target and the cap.
module accuracy_ladder
   use kinds, only: dp
   use accuracy_runs, only: run_t, launcher_t, nq, iq_force, iq_peak_time, state_done, predicted_run_cost, &
      error_scale, is_ladder
   implicit none
   private
   public :: axis_t, judged_t, choice_t, ladder_t, build_axes, judge_run, choose_run, final_run, ladder_run, &
             time_partner, cross_needed, done_run, weigh, estimate_t, ladder_estimate

   !> Factors of safety (module header) (-).
   real(dp), parameter :: richardson_safety = 1.25_dp, safe_factor = 1.5_dp, two_level_factor = 3.0_dp, &
      slow_cap = 5.0_dp

   !> The estimate of one result on one ladder.
   type :: estimate_t
      real(dp) :: error = huge(1.0_dp)     !< bound on |q(finest) - q(h -> 0)|, the result's unit
      real(dp) :: order = -1.0_dp          !< observed order, -1 when there is none
      logical :: asymptotic = .false.      !< the order is in the asymptotic range
      character(len=40) :: how = ''        !< which rule gave the error
      real(dp) :: floor = 0.0_dp           !< of which the resolution floor
   end type estimate_t

   integer, parameter :: axis_time = 1, axis_mesh = 2
   !> The results that are times read off the steps: the contact's duration, the time of the peak.
   logical, parameter :: time_results(nq) = [.false., .false., .true., .true., .false., .false., .false.]
   !> Orders: the method's, and the asymptotic range, of each axis; those the bisection for the
   !> observed order looks within.
   real(dp), parameter :: order_theory(2) = [2.0_dp, 2.0_dp], order_low(2) = [1.5_dp, 1.0_dp], &
      order_high(2) = [2.7_dp, 2.5_dp], order_min = 0.05_dp, order_max = 12.0_dp

   !> One axis: its levels done (from 0, without a gap) and their errors.
   type :: axis_t
      integer :: levels = 0                       !< levels done
      integer, allocatable :: run(:)              !< the run of each level (index into runs)
      real(dp), allocatable :: h(:), err(:, :)    !< size: dt (s) or 1/sqrt(nx ny); err(level, result)
      type(estimate_t) :: finest(nq)              !< the estimate of the finest level
   end type axis_t

   !> The runs, their axes and what they must meet.
   type :: ladder_t
      type(run_t), allocatable :: runs(:)         !< the ladder's runs and the model variants
      type(axis_t) :: tx, mx                      !< the time and mesh axes (build_axes)
      real(dp) :: target = 0.0_dp                 !< the relative error asked for
      logical :: estimated(nq) = .false., targeted(nq) = .false.   !< the results estimated, targeted
      integer :: k_max = 10                       !< the finest time level allowed
   end type ladder_t

   !> The run choose_run chose, and the cheapest the cap turned away.
   type :: choice_t
      integer :: k = 0, j = 0                     !< the run chosen
      logical :: found = .false.                  !< it meets the target
      logical :: beyond_cap = .false.             !< a run to make met the target but would pass the cap
      integer :: beyond_kj(2) = -1                !< the cheapest such run (k, j)
      real(dp) :: beyond_cost = huge(1.0_dp)      !< its predicted cost, its partner's included (s)
   end type choice_t

   !> A run's results with their errors (the results' units).
   type :: judged_t
      real(dp) :: value(nq) = 0.0_dp              !< the results (predicted for a run to come)
      !> the error's parts (time, mesh, their interaction, the spread of the maxima) and err, their sum
      real(dp), dimension(nq) :: err_time = 0.0_dp, err_mesh = 0.0_dp, err_cross = 0.0_dp, &
                                 err_maxima = 0.0_dp, err = 0.0_dp
      real(dp) :: worst = huge(1.0_dp)            !< largest err / (target |value|)
      logical :: meets = .false.                  !< every error within the target
      logical :: time_measured = .true.           !< its time error measured on its own mesh (time_on_mesh)
      logical :: two_levels = .false.             !< and from two time levels there (Roache's Fs = 3)
   end type judged_t

contains

   !> The error of the finest level of a ladder (module header).
   pure function ladder_estimate(h, q, order_theory, order_low, order_high, floor) result(e)
      real(dp), intent(in) :: h(:), q(:)       !< step or element size of each level, decreasing; the result at each
      real(dp), intent(in) :: order_theory     !< the method's order: no larger order is used
      real(dp), intent(in) :: order_low, order_high   !< the asymptotic range of orders
      real(dp), intent(in) :: floor            !< resolution added to the error (0: none)
      type(estimate_t) :: e
      real(dp) :: d1, d2, p, safe, ratio, richardson, lo, hi
      integer :: n, it
      n = size(q)
      e%floor = floor
      e%how = 'one level: no estimate'
      if (n < 2) return
      d2 = q(n - 1) - q(n)
      if (n == 2) then
         e%error = two_level_factor*abs(d2) + floor
         e%how = 'two levels: 3 x the difference'
         return
      end if
      d1 = q(n - 2) - q(n - 1)
      safe = safe_factor*max(abs(d1), abs(d2))
      if (d1 == 0.0_dp .and. d2 == 0.0_dp) then
         e%error = floor
         e%how = 'no change between the levels'
      else if (d1*d2 <= 0.0_dp) then
         e%error = safe + floor
         e%how = 'not monotone: 1.5 x largest difference'
      else
         lo = order_min;  hi = order_max         ! the observed order: f(p) = d1/d2 by bisection,
         bisect: do it = 1, 100                  ! order_min or order_max when outside their f
            p = 0.5_dp*(lo + hi)
            if (f(p) < d1/d2) lo = p
            if (f(p) >= d1/d2) hi = p
         end do bisect
         e%order = p
         e%asymptotic = p >= order_low .and. p <= order_high
         ratio = (h(n)/h(n - 1))**merge(min(p, order_theory), p, e%asymptotic)
         richardson = huge(1.0_dp)                 ! Richardson's error at that order
         if (ratio < 1.0_dp) richardson = abs(d2)*ratio/(1.0_dp - ratio)
         if (e%asymptotic) then
            e%error = richardson_safety*richardson + floor
            e%how = 'Richardson, order in range'
         else if (p < order_low) then
            e%error = max(min(richardson_safety*richardson, slow_cap*max(abs(d1), abs(d2))), safe) + floor
            e%how = 'slow: Richardson at observed order'
         else
            e%error = safe + floor
            e%how = 'order too high: 1.5 x largest diff.'
         end if
      end if
   contains
      !> (h1^x - h2^x)/(h2^x - h3^x) of the last three levels, scaled by h3 (it grows with x).
      pure real(dp) function f(x)
         real(dp), intent(in) :: x
         f = ((h(n - 2)/h(n))**x - (h(n - 1)/h(n))**x)/((h(n - 1)/h(n))**x - 1.0_dp)
      end function f
   end function ladder_estimate

   !> The run (k, j) of the ladder (not a model variant), 0 when there is none.
   pure integer function ladder_run(runs, k, j) result(i)
      type(run_t), intent(in) :: runs(:)
      integer, intent(in) :: k, j                 !< time and mesh level
      i = findloc(runs%k == k .and. runs%j == j .and. is_ladder(runs), .true., dim=1)
   end function ladder_run

   pure logical function done_run(runs, k, j)
      type(run_t), intent(in) :: runs(:)
      integer, intent(in) :: k, j
      done_run = any(runs%k == k .and. runs%j == j .and. is_ladder(runs) .and. runs%state == state_done)
   end function done_run

   subroutine build_axes(lad)
      type(ladder_t), intent(inout) :: lad
      call build_axis(lad%runs, axis_time, lad%estimated, lad%tx, 0, 0)
      call build_axis(lad%runs, axis_mesh, lad%estimated, lad%mx, 0, 0)
   end subroutine build_axes

   !> The axis (axis_time or axis_mesh) from the runs done, the error of each level; a time axis
   !> on mesh level j0 from time level k0.
   subroutine build_axis(runs, which, active, ax, j0, k0)
      type(run_t), intent(in) :: runs(:)
      integer, intent(in) :: which                !< axis_time or axis_mesh
      logical, intent(in) :: active(nq)           !< the results estimated
      type(axis_t), intent(out) :: ax
      integer, intent(in) :: j0, k0               !< a time axis's mesh level and first time level
      integer :: l, i, iq, k, j
      real(dp) :: floor, tail, steps(size(runs)), size_ratio, diff
      allocate (ax%run(0), ax%h(0))
      do l = 0, size(runs)
         k = merge(k0 + l, 0, which == axis_time);  j = merge(j0, l, which == axis_time)
         if (.not. done_run(runs, k, j)) exit
         i = ladder_run(runs, k, j)
         ax%run = [ax%run, i]
         ax%h = [ax%h, merge(runs(i)%dt, 1.0_dp/sqrt(real(runs(i)%nx, dp)*real(runs(i)%ny, dp)), which == axis_time)]
      end do
      ax%levels = l
      allocate (ax%err(l, nq), source=huge(1.0_dp))
      if (l == 0) return
      do iq = 1, nq
         if (.not. active(iq)) cycle
         associate (q => runs(ax%run)%q(iq), e => ax%finest(iq))
         steps(:l) = q/(runs(ax%run)%dt*1.0e6_dp)   ! a time (us) read off its run's steps: dt the floor
         floor = merge(runs(ax%run(l))%dt*1.0e6_dp, 0.0_dp, time_results(iq) .and. &
                       all(abs(steps(:l) - anint(steps(:l))) <= 1.0e-6_dp*max(1.0_dp, abs(steps(:l)))))
         e = ladder_estimate(ax%h, q, order_theory(which), order_low(which), order_high(which), floor)
         ! a mesh not resolving the Hertz disc (finest element over radius s/a > 1): the change
         ! still to come, like ln(1/h), the largest difference times the levels to go
         tail = 0.0_dp
         size_ratio = runs(ax%run(l))%h_impact/runs(ax%run(l))%contact_radius
         if (l >= 2) diff = maxval(abs(q(max(1, l - 2):l - 1) - q(max(2, l - 1):l)))
         if (which == axis_mesh .and. l >= 2 .and. size_ratio > 1.0_dp) &
            tail = max(0.0_dp, diff)*(log(size_ratio)/log(ax%h(l - 1)/ax%h(l)) + 1.0_dp)
         if (tail > 0.0_dp .and. (tail + floor > e%error .or. (e%order >= 0.0_dp .and. e%order < order_low(which)))) &
            then
            e%error = max(tail, safe_factor*diff) + floor
            e%how = 'contact disc unresolved: ln tail'
         end if
         ax%err(:, iq) = abs(q - q(l)) + e%error           ! each level's: its distance to the finest
         end associate
      end do
   end subroutine build_axis

   !> The results of run (k, j) and their errors (docs/ACCURACY.md); a run not done predicted as
   !> q(k,0) + q(0,j) - q(0,0), its time error no less than its mesh's at 2 dt over 2^2. The next
   !> time level on mesh 0 (k = tx%levels, not yet planned): a result converging at p in range
   !> continued by p, its error the axis's rule with that level; any other the finest level's (a
   !> safe bound predicts no gain).
   function judge_run(lad, k, j) result(jd)
      type(ladder_t), intent(in) :: lad
      integer, intent(in) :: k, j                 !< the levels (k <= tx%levels, j < mx%levels; j = 0 for k = tx%levels)
      type(judged_t) :: jd
      type(estimate_t) :: next
      integer :: i, ik, ij, i0, n, iq
      real(dp) :: below(nq), h(lad%tx%levels + 1), q(lad%tx%levels + 1), p
      logical :: measured, known, two
      associate (runs => lad%runs, tx => lad%tx)
      n = tx%levels
      do i = 1, size(runs)                        ! the largest interaction of the combined runs done
         if (runs(i)%state /= state_done .or. runs(i)%role /= 'combined') cycle
         if (runs(i)%k >= n .or. runs(i)%j >= lad%mx%levels) cycle
         jd%err_cross = max(jd%err_cross, abs(runs(i)%q - runs(tx%run(runs(i)%k + 1))%q &
                                              - runs(lad%mx%run(runs(i)%j + 1))%q + runs(tx%run(1))%q))
      end do
      if (k >= n) then                            ! the next time level
         jd%value = runs(tx%run(n))%q;  jd%err_time = tx%finest%error;  jd%err_mesh = lad%mx%err(1, :)
         h(:n) = tx%h;  h(n + 1) = tx%h(n)/2.0_dp
         do iq = 1, nq
            p = tx%finest(iq)%order
            if (.not. lad%targeted(iq) .or. p <= 0.0_dp .or. p > order_high(axis_time)) cycle
            q(:n) = runs(tx%run)%q(iq)            ! and the next level's value, continued at order p
            q(n + 1) = q(n) - (q(n - 1) - q(n))*(h(n + 1)**p - h(n)**p)/(h(n)**p - h(n - 1)**p)
            next = ladder_estimate(h, q, order_theory(axis_time), order_low(axis_time), order_high(axis_time), &
                                   tx%finest(iq)%floor/2.0_dp)
            jd%value(iq) = q(n + 1);  jd%err_time(iq) = next%error
         end do
         call weigh(jd, runs(tx%run(n)), lad, .true.)
         return
      end if
      i0 = tx%run(1);  ik = tx%run(k + 1);  ij = lad%mx%run(j + 1)
      i = merge(ladder_run(runs, k, j), 0, done_run(runs, k, j))
      jd%value = runs(ik)%q + runs(ij)%q - runs(i0)%q
      if (i > 0) then
         jd%value = runs(i)%q
         jd%err_cross = max(abs(runs(i)%q - runs(ik)%q - runs(ij)%q + runs(i0)%q), jd%err_cross)
      end if
      jd%err_time = tx%err(k + 1, :);  jd%err_mesh = lad%mx%err(j + 1, :)
      measured = .true.
      if (j > 0) call time_on_mesh(lad, k, j, jd%err_time, measured, jd%two_levels)
      if (i == 0 .and. j > 0 .and. k > 0) then     ! a run to come: its mesh's time error at dt x 2, the order's share
         below = 0.0_dp
         call time_on_mesh(lad, k - 1, j, below, known, two)
         if (known) jd%err_time = max(jd%err_time, below/2.0_dp**order_theory(axis_time))
      end if
      ! a run to come: predicted, judged again when done; its maxima its mesh's
      call weigh(jd, runs(merge(i, ij, i > 0)), lad, measured .or. i == 0)
      end associate
   end function judge_run

   !> A judgement's sum, the spread of the maxima added to the time of the peak, the worst ratio
   !> of error to target and whether it meets the target (measured: its time error on its mesh).
   !> The spread: the largest |t_i - t_peak| over the other maxima within the peak force's error
   !> of it, F_i >= F - e_F (0 without).
   pure subroutine weigh(jd, maxima_run, lad, measured)
      type(judged_t), intent(inout) :: jd         !< the judgement, its parts set
      type(run_t), intent(in) :: maxima_run       !< the run whose maxima count
      type(ladder_t), intent(in) :: lad           !< the ladder (the target, the results targeted)
      logical, intent(in) :: measured             !< the time error measured on its mesh
      real(dp) :: scale(nq)
      integer :: i
      jd%err = jd%err_time + jd%err_mesh + jd%err_cross
      associate (mx => maxima_run%maxima, has_peak => maxima_run%has(iq_peak_time))
      if (jd%err(iq_force) < huge(1.0_dp) .and. has_peak .and. allocated(mx%f_n)) then
         jd%err_maxima(iq_peak_time) = max(0.0_dp, maxval(abs(mx%t_us - jd%value(iq_peak_time)), &
            mask=mx%f_n >= jd%value(iq_force) - jd%err(iq_force) .and. &
                 [(i /= maxloc(mx%f_n, dim=1), i = 1, size(mx%f_n))]))
         jd%err(iq_peak_time) = jd%err(iq_peak_time) + jd%err_maxima(iq_peak_time)
      end if
      end associate
      scale = lad%target*error_scale(jd%value)
      jd%worst = max(0.0_dp, maxval(jd%err/merge(scale, 1.0_dp, scale > 0.0_dp), &
                                    mask=lad%targeted .and. scale > 0.0_dp))
      if (any(lad%targeted .and. scale <= 0.0_dp .and. jd%err > 0.0_dp)) jd%worst = huge(1.0_dp)
      jd%meets = jd%worst <= 1.0_dp .and. measured;  jd%time_measured = measured
   end subroutine weigh

   !> The time error of run (k, j), j > 0, from the time levels done on mesh j next to k (at
   !> least two), no less than mesh 0's; two levels in the asymptotic range: Roache's GCI.
   subroutine time_on_mesh(lad, k, j, err_time, measured, two)
      type(ladder_t), intent(in) :: lad
      integer, intent(in) :: k, j
      real(dp), intent(inout) :: err_time(nq)     !< mesh 0's time error in; the larger out
      logical, intent(out) :: measured            !< a neighbouring time level done on mesh j
      logical, intent(out) :: two                 !< measured from two levels only
      type(axis_t) :: ax
      real(dp) :: finest
      integer :: iq, k0
      do k0 = k, 1, -1                              ! the first of the time levels done next to k
         if (.not. done_run(lad%runs, k0 - 1, j)) exit
      end do
      call build_axis(lad%runs, axis_time, lad%targeted, ax, j, k0)
      measured = ax%levels >= 2 .and. k - k0 < ax%levels;  two = measured .and. ax%levels == 2
      if (.not. measured) return
      do iq = 1, nq
         if (.not. lad%targeted(iq)) cycle
         associate (q => lad%runs(ax%run)%q(iq))
         finest = ax%finest(iq)%error             ! two levels in range: Roache's GCI (Fs = 3)
         if (two .and. lad%tx%finest(iq)%asymptotic) finest = two_level_factor*abs(q(1) - q(2)) &
            /((ax%h(1)/ax%h(2))**order_theory(axis_time) - 1.0_dp) + ax%finest(iq)%floor
         err_time(iq) = max(err_time(iq), abs(q(k - k0 + 1) - q(ax%levels)) + finest)
         end associate
      end do
   end subroutine time_on_mesh

   !> The time level whose run on mesh j would measure run (k, j)'s time error: k - 1, or 1 for
   !> k = 0; -1 when none is needed (j = 0, or a neighbour is done).
   pure integer function time_partner(runs, k, j) result(p)
      type(run_t), intent(in) :: runs(:)
      integer, intent(in) :: k, j
      p = merge(-1, merge(k - 1, 1, k > 0), j == 0 .or. done_run(runs, k - 1, j) .or. &
                done_run(runs, k + 1, j))
   end function time_partner

   !> Whether run (k, j) (mesh 0, below dt0) needs the run (1, 1): no interaction measured yet.
   pure logical function cross_needed(runs, k, j)
      type(run_t), intent(in) :: runs(:)
      integer, intent(in) :: k, j
      cross_needed = k > 0 .and. j == 0 .and. .not. any(runs%state == state_done .and. runs%role == 'combined')
   end function cross_needed

   !> The cheapest run (k, j) meeting the target, priced with the runs it still needs (its time
   !> partner, (1, 1) while cross_needed); past the cap: beyond_cap; none: the least worst done.
   function choose_run(lad, la) result(c)
      type(ladder_t), intent(in) :: lad
      type(launcher_t), intent(in) :: la          !< the launcher (its cost model, the cap, the cpu time spent)
      type(choice_t) :: c
      type(judged_t) :: jd
      real(dp) :: cost, best_cost, best_worst
      integer :: kk, jj, p
      logical :: done
      best_cost = huge(1.0_dp);  best_worst = huge(1.0_dp)
      do kk = 0, merge(lad%tx%levels, lad%tx%levels - 1, lad%tx%levels <= lad%k_max)
         do jj = 0, merge(0, lad%mx%levels - 1, kk == lad%tx%levels)
            jd = judge_run(lad, kk, jj)
            done = done_run(lad%runs, kk, jj);  p = time_partner(lad%runs, kk, jj)
            cost = merge(0.0_dp, run_cost(kk, jj), done)
            if (p >= 0) cost = cost + run_cost(p, jj)     ! a partner is never done (time_partner)
            if (cross_needed(lad%runs, kk, jj) .and. lad%mx%levels > 1) cost = cost + run_cost(1, 1)
            if (jd%worst <= 1.0_dp .and. cost > 0.0_dp .and. la%spent + cost > la%cap) then
               if (cost < c%beyond_cost) c%beyond_kj = [kk, jj]
               c%beyond_cost = min(c%beyond_cost, cost)
            else if (jd%worst <= 1.0_dp) then
               if (.not. c%found .or. cost < best_cost .or. (cost == best_cost .and. jd%worst < best_worst)) then
                  c%found = .true.;  c%k = kk;  c%j = jj;  best_cost = cost;  best_worst = jd%worst
               end if
            else if (.not. c%found .and. done .and. jd%worst < best_worst) then
               c%k = kk;  c%j = jj;  best_worst = jd%worst
            end if
         end do
      end do
      c%beyond_cap = c%beyond_kj(1) >= 0 .and. .not. c%found
   contains
      !> The predicted cost of the run (k, j): what the cost model reads, k, nx, ny.
      real(dp) function run_cost(kr, jr)
         integer, intent(in) :: kr, jr
         type(run_t) :: probe
         probe = lad%runs(lad%mx%run(jr + 1));  probe%k = kr   ! a ladder run: cost_factor 1
         run_cost = predicted_run_cost(probe, la)
      end function run_cost
   end function choose_run

   !> The run done meeting the target with the least worst ratio, else the least worst ratio.
   function final_run(lad) result(kj)
      type(ladder_t), intent(in) :: lad
      integer :: kj(2)
      type(judged_t) :: jd
      real(dp) :: best(2)
      integer :: kk, jj, other(2)
      best = huge(1.0_dp);  kj = -1;  other = 0
      do kk = 0, lad%tx%levels - 1
         do jj = 0, lad%mx%levels - 1
            if (.not. done_run(lad%runs, kk, jj)) cycle
            jd = judge_run(lad, kk, jj)
            if (jd%meets .and. .not. cross_needed(lad%runs, kk, jj) .and. jd%worst < best(1)) &
               kj = [kk, jj]
            if (all(kj == [kk, jj])) best(1) = jd%worst
            if (jd%worst < best(2)) other = [kk, jj]
            best(2) = min(best(2), jd%worst)
         end do
      end do
      if (kj(1) < 0) kj = other
   end function final_run

end module accuracy_ladder
