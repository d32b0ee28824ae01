!> The runs of an accuracy run: each the program itself, a child process (child_process):
!> impact --single [--restart] [the user's --set ...] --set output.prefix='<prefix>_acc/<run>'
!> and its settings; its output in <prefix>_acc/<run>.log, its results read from its summary.
!> run_planned starts them, as many at a time as there are CPUs, the dearest first, each only
!> within the cap. The cost model: on a mesh already run, that run's cost times 2^(k - k');
!> else c 2^k (n/n0)^gamma, gamma fitted between the two finest meshes at dt0, c to the
!> costliest run done (docs/PERFORMANCE.md).
module accuracy_runs
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use kinds, only: dp, msg_len
   use number_text, only: int_str, real_str, real_short
   use result_reader, only: summary_t, read_summary, summary_value, summary_has, summary_string, read_columns
   use child_process, only: spawn_program, wait_child, stop_caught
   use result_files, only: col_time, col_force
   use scene_model, only: scene_t
   implicit none
   private
   public :: nq, iq_force, iq_peak_time, iq_failure, result_keys, result_units, run_t, launcher_t, run_planned, &
      maxima_t, force_maxima, state_planned, state_done, state_failed, state_skipped, state_stopped, fit_costs, &
      predicted_run_cost, ladder_name, error_scale, is_ladder

   !> The results an accuracy run estimates: their summary keys and units (the last two: with
   !> &strength, with ply damage).
   integer, parameter :: nq = 7
   character(len=*), parameter :: result_keys(nq) = [character(len=19) :: 'peak_force_N', 'max_deflection_mm', &
      'contact_duration_us', 'time_of_peak_us', 'max_strain_y_back', 'max_failure_index', 'damage_dissipated_J']
   character(len=*), parameter :: result_units(nq) = [character(len=2) :: 'N', 'mm', 'us', 'us', '-', '-', 'J']
   !> The places in result_keys of the peak force, the contact duration, the time of the peak, the failure index.
   integer, parameter :: iq_force = 1, iq_duration = 3, iq_peak_time = 4, iq_failure = 6

   !> States of a run (stopped: by a stop signal to the accuracy run); a variant's settings, at most.
   integer, parameter :: state_planned = 0, state_running = 1, state_done = 2, state_failed = 3, state_skipped = 4, &
                         state_stopped = 5, max_variant = 4
   !> The cost model's exponent of the element count before two meshes are measured, and its bounds.
   real(dp), parameter :: gamma_default = 1.8_dp, gamma_min = 1.0_dp, gamma_max = 3.0_dp

   !> The local maxima of a run's force (a row above the one before and not below the one after).
   type :: maxima_t
      real(dp), allocatable :: t_us(:), f_n(:)    !< their times (us), their forces (N)
   end type maxima_t

   !> One run of the ladder, or a model variant at the chosen settings.
   type :: run_t
      character(len=48) :: name = ''              !< its name: <prefix>_acc/<name>_summary.dat
      character(len=12) :: role = ''              !< 'time', 'mesh', 'combined', 'theory' or 'bend_twist'
      integer :: k = 0, j = 0                     !< time level (dt = dt0/2^k), mesh level
      integer :: nx = 0, ny = 0                   !< elements (&mesh nx, ny)
      real(dp) :: dt = 0.0_dp, grading = 1.0_dp   !< time step (s), &mesh grading
      character(len=64) :: variant(max_variant) = ''   !< the variant's settings, 'group.var=value'
      real(dp) :: cost_factor = 1.0_dp            !< the variant's domain, in quarters
      integer :: state = state_planned            !< state_planned, ...
      integer :: pid = -1, exit_code = 0          !< its process while it runs, its exit status
      real(dp) :: cpu_s = 0.0_dp                  !< its cpu time, from its summary (s)
      real(dp) :: q(nq) = 0.0_dp                  !< its results, result_keys' units
      logical :: has(nq) = .false.                !< which it has
      character(len=256) :: status = ''            !< its summary's status
      real(dp) :: h_impact = 0.0_dp               !< side of the element at the impact point, the larger (m)
      real(dp) :: contact_radius = 0.0_dp         !< Hertz contact radius at its peak force (m)
      type(maxima_t) :: maxima                    !< the force's local maxima (its history file)
   end type run_t

   !> What starting a run needs, and the spending so far.
   type :: launcher_t
      character(len=:), allocatable :: exe, deck_path, dir   !< the program, the deck, '<prefix>_acc/'
      character(len=8192), allocatable :: user_settings(:)   !< the user's --set values, in order
      character(len=32) :: theory = ''            !< the theory of every ladder run
      type(scene_t) :: scene                      !< the scene of the deck's model (domain, D16, D26)
      logical :: every_step = .false.             !< history every step (&strength: the failure index)
      logical :: restart = .false.                !< --restart: each run continues from its restart point
      integer :: cpus = 1, n0 = 1                 !< runs at a time; elements of mesh level 0 (nx ny)
      real(dp) :: impact_element(2) = 0.0_dp      !< sides of the element at the impact point, level 0 (m)
      real(dp) :: gauge(2) = 0.0_dp               !< the strain gauge of level 0 (m, from the plate centre)
      real(dp) :: cap = huge(1.0_dp)              !< &accuracy max_cpu_s (s)
      integer :: cap_times = 0                    !< > 0: the cap this many times the first run's cpu time
      real(dp) :: spent = 0.0_dp                  !< cpu time of the runs done (s)
      real(dp) :: c_base = -1.0_dp                !< cost of a level-0 run (s), < 0: unknown
      real(dp) :: gamma = gamma_default           !< the cost's exponent of the element count
      type(run_t), allocatable :: anchors(:)      !< the ladder runs done (fit_costs)
      logical :: cap_reached = .false.            !< a run was skipped for the cap
      integer :: unit = 6                         !< where progress goes
   end type launcher_t

contains

   !> Starts the planned runs within the cap (module header) and waits for all; stat /= 0 when a
   !> run could not be started (a run that fails is state_failed).
   subroutine run_planned(runs, la, stat, errmsg)
      type(run_t), intent(inout) :: runs(:)
      type(launcher_t), intent(inout) :: la
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer :: i, pid, code, running
      real(dp) :: cost(size(runs))
      character(len=48), allocatable :: names(:)
      logical :: known
      stat = 0;  running = 0
      do
         launch: do while (running < la%cpus .and. stat == 0 .and. stop_caught() == 0)
            cost = predicted_run_cost(runs, la)
            i = 0   ! the next: the dearest planned; while the costs are unknown the cheapest alone
            if (la%c_base >= 0.0_dp) i = maxloc(cost, mask=runs%state == state_planned, dim=1)
            if (la%c_base < 0.0_dp .and. running == 0) i = minloc(cost, mask=runs%state == state_planned, dim=1)
            if (i == 0) exit launch
            if (la%c_base >= 0.0_dp .and. &
                la%spent + sum(cost, mask=runs%state == state_running) + cost(i) > la%cap) then
               runs(i)%state = state_skipped;  la%cap_reached = .true.
               cycle launch
            end if
            call spawn_program(la%exe, run_settings(runs(i), la), la%dir // trim(runs(i)%name) // '.log', runs(i)%pid, &
                               stat, errmsg)
            runs(i)%state = merge(state_running, state_failed, stat == 0)
            if (stat == 0) running = running + 1
         end do launch
         if (running == 0) exit
         call wait_child(pid, code)
         if (pid < 0) errmsg = 'waitpid: the runs started are gone'
         stat = merge(1, stat, pid < 0)
         if (pid < 0) exit
         i = findloc(runs%pid, pid, dim=1)
         if (i == 0) cycle
         running = running - 1
         runs(i)%pid = -1;  runs(i)%exit_code = code
         if (stop_caught() /= 0 .and. code /= 0) runs(i)%state = state_stopped   ! restart point kept
         if (runs(i)%state == state_stopped) cycle
         known = la%c_base >= 0.0_dp
         call finish_run(runs(i), la)
         call fit_costs(runs, la)
         if (known .or. la%c_base < 0.0_dp) cycle
         ! the first run done: the cap, when a multiple of it, and the price on standard output
         if (la%cap_times > 0) la%cap = real(la%cap_times, dp)*la%spent
         cost = merge(predicted_run_cost(runs, la), 0.0_dp, runs%state == state_planned)
         names = pack(runs%name, runs%state == state_planned)
         write (la%unit, '(*(a))') 'accuracy: next,', (' ' // trim(names(i)), i = 1, size(names)), &
            ': predicted ', real_short(sum(cost)), ' s of cpu, ', real_short(max(maxval(cost), sum(cost)/la%cpus)), &
            ' s of wall; then more levels while the target is not met, within the cap of ', real_short(la%cap), &
            ' s of cpu'
         flush (la%unit)
      end do
      if (stop_caught() /= 0) where (runs%state == state_planned) runs%state = state_stopped
      la%cap_reached = la%cap_reached .or. (stat == 0 .and. any(runs%state == state_planned))
      if (stat == 0) where (runs%state == state_planned) runs%state = state_skipped
   end subroutine run_planned

   !> The cost model's prediction of a run's cpu time (s; 0 while nothing is known): the run done
   !> on its mesh at the time level nearest its own (the finer of two), else c 2^k (n/n0)^gamma.
   elemental real(dp) function predicted_run_cost(run, la)
      type(run_t), intent(in) :: run               !< the run (its k, nx, ny, cost_factor)
      type(launcher_t), intent(in) :: la           !< the launcher (its cost model)
      integer :: a
      predicted_run_cost = max(la%c_base, 0.0_dp)*relative_cost(run, la)
      if (.not. allocated(la%anchors)) return
      ! the nearest k, of two as near the finer (k < 100)
      a = minloc(100*abs(la%anchors%k - run%k) - la%anchors%k, mask=la%anchors%nx == run%nx .and. &
                 la%anchors%ny == run%ny .and. la%anchors%cost_factor == run%cost_factor, dim=1)
      if (a > 0) predicted_run_cost = la%anchors(a)%cpu_s*2.0_dp**(run%k - la%anchors(a)%k)
   end function predicted_run_cost

   !> What each result's error is relative to: its size; for the time of the peak the duration.
   pure function error_scale(q) result(scale)
      real(dp), intent(in) :: q(nq)
      real(dp) :: scale(nq)
      scale = abs(q)
      scale(iq_peak_time) = abs(q(iq_duration))
   end function error_scale

   !> The name of the ladder run (k, j): t<k>_m<j>.
   pure function ladder_name(k, j) result(name)
      integer, intent(in) :: k, j                  !< its time and mesh levels
      character(len=:), allocatable :: name
      name = 't' // int_str(k) // '_m' // int_str(j)
   end function ladder_name

   !> True for a run of the ladder, false for a model variant.
   elemental logical function is_ladder(run)
      type(run_t), intent(in) :: run
      is_ladder = run%role /= 'theory' .and. run%role /= 'bend_twist'
   end function is_ladder

   !> The cost model fitted to the runs done (module header).
   subroutine fit_costs(runs, la)
      type(run_t), intent(in) :: runs(:)
      type(launcher_t), intent(inout) :: la
      integer :: i, finest, next
      real(dp) :: ratio
      logical :: at_dt0(size(runs))
      at_dt0 = runs%state == state_done .and. is_ladder(runs) .and. runs%k == 0   ! the two finest meshes there
      finest = maxloc(runs%j, mask=at_dt0, dim=1)
      if (finest > 0) at_dt0(finest) = .false.
      next = maxloc(runs%j, mask=at_dt0, dim=1)
      if (next > 0) then
         ratio = real(runs(finest)%nx, dp)*real(runs(finest)%ny, dp)/(real(runs(next)%nx, dp)*real(runs(next)%ny, dp))
         if (ratio > 1.0_dp .and. runs(next)%cpu_s > 0.0_dp .and. runs(finest)%cpu_s > 0.0_dp) &
            la%gamma = min(gamma_max, max(gamma_min, log(runs(finest)%cpu_s/runs(next)%cpu_s)/log(ratio)))
      end if
      la%anchors = pack(runs, runs%state == state_done .and. is_ladder(runs))
      ! c from the costliest run done: the best guide to the costly runs to come
      i = maxloc(runs%cpu_s, mask=runs%state == state_done, dim=1)
      if (i > 0) la%c_base = runs(i)%cpu_s/relative_cost(runs(i), la)
   end subroutine fit_costs

   !> A run's cost in units of c: 2^k (n/n0 cost_factor)^gamma, n = nx ny.
   pure real(dp) function relative_cost(run, la)
      type(run_t), intent(in) :: run               !< the run (its k, nx, ny, cost_factor)
      type(launcher_t), intent(in) :: la           !< the launcher (n0, gamma)
      relative_cost = 2.0_dp**run%k*(real(run%nx, dp)*real(run%ny, dp)/real(la%n0, dp) &
                                     *run%cost_factor)**la%gamma
   end function relative_cost

   !> The arguments of a run, without the program.
   function run_settings(run, la) result(args)
      type(run_t), intent(in) :: run
      type(launcher_t), intent(in) :: la
      character(len=8192), allocatable :: args(:), sets(:)
      character(len=:), allocatable :: prefix
      integer :: i
      prefix = la%dir // trim(run%name)
      quoted: do i = len(prefix), 1, -1                  ! as a deck's quoted text: a quote in it doubled
         if (prefix(i:i) == "'") prefix = prefix(:i) // prefix(i:)
      end do quoted
      args = [character(len=8192) :: '--single']       ! one run: the deck's &accuracy left aside
      if (la%restart) args = [args, [character(len=8192) :: '--restart']]
      sets = [character(len=8192) :: la%user_settings, "output.prefix='" // prefix // "'", &
         'output.overwrite=.true.', 'output.hdf5=.false.']
      if (la%every_step) sets = [sets, [character(len=8192) :: 'output.every=1']]
      sets = [character(len=8192) :: sets, 'analysis.dt=' // real_str(run%dt), 'mesh.nx=' // int_str(run%nx), &
         'mesh.ny=' // int_str(run%ny), 'mesh.grading=' // real_str(run%grading), &
         'output.gauge_x=' // real_str(la%gauge(1)), 'output.gauge_y=' // real_str(la%gauge(2)), &   ! level 0's gauge
         "analysis.theory='" // trim(la%theory) // "'", pack(run%variant, len_trim(run%variant) > 0)]
      args = [args, [character(len=8192) :: ([character(len=8192) :: '--set', sets(i)], i = 1, size(sets)), &
                     la%deck_path]]
   end function run_settings

   !> A run that ended: its summary read, its state, one line of progress.
   subroutine finish_run(run, la)
      type(run_t), intent(inout) :: run
      type(launcher_t), intent(inout) :: la        !< the launcher (its spending)
      type(summary_t) :: s
      character(len=msg_len) :: errmsg
      character(len=:), allocatable :: line
      integer :: stat, iq
      call read_summary(la%dir // trim(run%name) // '_summary.dat', s, stat, errmsg)
      run%state = merge(state_done, state_failed, stat == 0 .and. run%exit_code == 0)
      run%status = 'no summary (' // la%dir // trim(run%name) // '.log)'
      if (stat /= 0) return
      if (summary_has(s, 'status')) run%status = summary_string(s, 'status')
      run%cpu_s = max(0.0_dp, summary_value(s, 'cpu_s', 0.0_dp))
      la%spent = la%spent + run%cpu_s
      line = 'accuracy: run ' // trim(run%name) // ': dt ' // real_short(run%dt*1.0e6_dp) // ' us, mesh ' // &
         int_str(run%nx) // ' x ' // int_str(run%ny)
      do iq = 1, nq
         run%has(iq) = summary_has(s, result_keys(iq))
         run%q(iq) = summary_value(s, result_keys(iq), ieee_value(0.0_dp, ieee_quiet_nan))
         if (run%has(iq)) line = line // ', ' // trim(result_keys(iq)) // ' ' // real_short(run%q(iq))
      end do
      if (run%state == state_done) call force_maxima(la%dir // trim(run%name) // '_history.dat', run%maxima)
      line = line // ', cpu ' // real_short(run%cpu_s) // ' s'
      if (run%state /= state_done) line = line // ': ' // trim(run%status)
      write (la%unit, '(a)') line
      flush (la%unit)
   end subroutine finish_run

   !> The force's maxima in a run's history file, those of at least half the largest; none when it
   !> cannot be read.
   subroutine force_maxima(path, mx)
      character(len=*), intent(in) :: path        !< <prefix>_history.dat
      type(maxima_t), intent(out) :: mx           !< its maxima
      real(dp), allocatable :: h(:, :)
      logical, allocatable :: top(:)
      integer :: stat, n
      call read_columns(path, max(col_time, col_force), h, stat)
      n = size(h, 2)
      allocate (top(n), source=.false.)
      if (stat == 0 .and. n >= 3) top(2:n - 1) = h(col_force, 2:n - 1) > h(col_force, :n - 2) .and. &
                                                h(col_force, 2:n - 1) >= h(col_force, 3:)
      if (any(top)) top = top .and. h(col_force, :) >= 0.5_dp*maxval(h(col_force, :), mask=top)
      mx%t_us = pack(h(col_time, :), top)
      mx%f_n = pack(h(col_force, :), top)
   end subroutine force_maxima

end module accuracy_runs
