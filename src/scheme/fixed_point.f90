!> The guard of Akay's nonlinear iteration (eq. 19, stopped by eq. 18) and
!> its fall-back: a residual that is not finite, grows or stagnates ends the
!> plain iteration, and Anderson mixing takes over (above fp_guard_t); with
!> guard%accelerate it is the iteration itself from the fifth iterate (above
!> fp_next); convergence is eq. (18) on the map's residual, or its estimate
!> with the contraction (above fp_check). Never a silent wrong answer.
!> Usage, once per plate solution:
!>     call fp_start(guard, n, max_iter, cr2)
!>     do
!>        g = G(d)                                   ! one back substitution
!>        call fp_check(guard, d, g, d_t)            ! converged? diverging?
!>        if (guard%state /= fp_iterating) exit      ! converged or failed
!>        call fp_next(guard, d, g, stat, errmsg)    ! d <- next iterate
!>     end do
!> More: docs/STABILITY.md.
module fixed_point
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use kinds, only: dp, msg_len
   use number_text, only: int_str
   implicit none
   private
   public :: fp_guard_t, fp_start, fp_check, fp_next, fp_report
   public :: fp_iterating, fp_converged, fp_not_finite, fp_diverged, fp_stagnated, fp_limit


   !> States of the iteration.
   integer, parameter :: fp_iterating = 0   !< going on
   integer, parameter :: fp_converged = 1   !< eq. (18) met
   integer, parameter :: fp_not_finite = 2  !< a residual was NaN or Inf (after the fall-back)
   integer, parameter :: fp_diverged = 3    !< the residual kept growing (after the fall-back)
   integer, parameter :: fp_stagnated = 4   !< the residual stopped falling (after the fall-back)
   integer, parameter :: fp_limit = 5       !< max_nonlinear_iter iterations used

   !> Residual growths in a row that mean divergence.
   integer, parameter :: growth_limit = 3
   !> Iterations over which the squared residual must fall by progress_factor.
   integer, parameter :: stagnation_window = 10
   !> Least fall of the squared residual over stagnation_window iterations
   !> (0.5: a contraction factor above 0.5^(1/20) = 0.966 per iteration is
   !> too slow to reach C_r2 within the iteration limit).
   real(dp), parameter :: progress_factor = 0.5_dp
   !> Iterations of the mixing over which its best squared residual must
   !> fall by progress_factor.
   integer, parameter :: mixing_window = 2*stagnation_window
   !> A mixing residual this many times the best so far restarts the mixing
   !> from the best iterate.
   real(dp), parameter :: restart_factor = 1.0e3_dp
   !> Previous iterates combined by Anderson mixing.
   integer, parameter :: anderson_depth = 5
   !> Accelerated, the last plain iteration: the mixing makes the next
   !> iterate (above fp_next).
   integer, parameter :: first_mixed = 4
   !> Relative size below which the least-squares problem of the mixing is
   !> treated as rank deficient (dgelsy's rcond).
   real(dp), parameter :: mixing_rcond = 1.0e-10_dp
   !> Residual (relative to D) at the rounding level: (8 eps)^2 of sum D^2.
   real(dp), parameter :: round_floor = (8.0_dp*epsilon(1.0_dp))**2
   !> Largest eq. (18) ratio the rate test accepts: an iterate whose change
   !> is over a third of the step's is not trusted to the estimate.
   real(dp), parameter :: rate_test_max_ratio = 0.1_dp

   !> Eq. (19) is a fixed-point iteration D^{n+1} = G(D^n): the nonlinear
   !> stiffness is moved to the right-hand side so that the left-hand matrix
   !> K_L + 4/dt^2 M never changes. It converges when the nonlinear (membrane)
   !> stiffness is small against K_L + 4/dt^2 M; with large deflections, thin
   !> plates or long time steps the iteration matrix -(K_L + 4/dt^2 M)^-1 K_N'
   !> has eigenvalues beyond -1 and the plain iteration oscillates with a
   !> growing amplitude (docs/STABILITY.md). The guard watches the residual
   !> R = G(D) - D of every iteration and stops the plain iteration when
   !>  - a residual is not finite (NaN or Inf),
   !>  - the residual grew in growth_limit iterations in a row (divergence), or
   !>  - the residual fell by less than a factor progress_factor over the last
   !>    stagnation_window iterations (stagnation).
   !> It then falls back to Anderson mixing (Walker & Ni, SIAM J. Numer. Anal.
   !> 49, 2011): the next iterate combines the last anderson_depth iterates so
   !> as to minimise the linearised residual, a quasi-Newton step that needs no
   !> new factorisation and converges where the plain iteration diverges
   !> (for a linear problem it is GMRES). Mixing restarts from the iterate with
   !> the smallest residual so far. If mixing too diverges, stagnates or runs
   !> out of iterations, the guard says so (state) and the caller stops the run
   !> with a diagnostic: never a silent wrong answer.
   !>
   !> The state of one fixed-point iteration and its history.
   type :: fp_guard_t
      integer :: state = fp_iterating     !< fp_iterating, fp_converged or why it stopped
      integer :: iterations = 0           !< evaluations of G so far
      integer :: max_iter = 0             !< limit of the iterations
      real(dp) :: cr2 = 0.0_dp            !< tolerance of eq. (18)
      real(dp) :: ratio = huge(1.0_dp)    !< last eq. (18) ratio sum R^2 / sum (G - D_t)^2
      logical :: rate_test = .false.      !< also accept on the estimated next change (above fp_check)
      logical :: accelerate = .false.     !< Anderson mixing from the fifth iterate on, not only as a fall-back
      real(dp) :: theta2_first = 1.0_dp   !< theta^2 of the rate test's first iteration
      real(dp) :: ratios_before(2) = huge(1.0_dp)  !< the eq. (18) ratios of the two iterations before the last
      real(dp) :: plain_theta2 = huge(1.0_dp)      !< theta^2 of the rate test from the third iteration on (plain map)
      real(dp) :: res = huge(1.0_dp)      !< last sum R^2 (m^2, rad^2)
      real(dp) :: res_best = huge(1.0_dp) !< smallest sum R^2 so far
      integer :: growths = 0              !< residual growths in a row
      logical :: mixing = .false.         !< the fall-back (Anderson mixing) is engaged
      logical :: restart = .false.        !< the next iterate is d_best (mixing just engaged, or a jump)
      integer :: restarts = 0             !< restarts of the mixing after a jump
      integer :: mixing_from = 0          !< iteration at which it was engaged
      integer :: mixing_cause = fp_iterating  !< why: fp_not_finite, fp_diverged or fp_stagnated
      integer :: window_start = 1         !< first iteration of the stagnation window
      real(dp), allocatable :: window(:)  !< sum R^2 of each iteration (stagnation test)
      real(dp), allocatable :: d_best(:)  !< the iterate with the smallest residual
      integer :: ncol = 0                 !< columns of the mixing history in use
      integer :: newest = 0               !< the column of df, dg written last (a ring of anderson_depth)
      real(dp), allocatable :: df(:,:)    !< differences of successive residuals
      real(dp), allocatable :: dg(:,:)    !< differences of successive G values
      real(dp), allocatable :: f_last(:)  !< last residual
      real(dp), allocatable :: g_last(:)  !< last G value
      logical :: has_last = .false.       !< f_last, g_last hold the previous iteration
   end type fp_guard_t

   interface
      !> LAPACK: minimum-norm least squares by complete orthogonal factorisation.
      subroutine dgelsy(m, n, nrhs, a, lda, b, ldb, jpvt, rcond, rank, work, lwork, info)
         import :: dp
         integer, intent(in) :: m, n, nrhs, lda, ldb, lwork
         real(dp), intent(inout) :: a(lda, *), b(ldb, *)
         integer, intent(inout) :: jpvt(*)
         real(dp), intent(in) :: rcond
         integer, intent(out) :: rank, info
         real(dp), intent(inout) :: work(*)
      end subroutine dgelsy
   end interface

contains

   !> A fresh guard for an iteration on n unknowns.
   subroutine fp_start(guard, n, max_iter, cr2)
      type(fp_guard_t), intent(inout) :: guard  !< guard, reset (its arrays are reused)
      integer, intent(in) :: n                  !< number of unknowns
      integer, intent(in) :: max_iter           !< most evaluations of G
      real(dp), intent(in) :: cr2               !< tolerance C_r2 of eq. (18)
      guard%state = fp_iterating
      guard%iterations = 0
      guard%max_iter = max_iter
      guard%cr2 = cr2
      guard%ratio = huge(1.0_dp)
      guard%rate_test = .false.
      guard%accelerate = .false.
      guard%theta2_first = 1.0_dp
      guard%ratios_before = huge(1.0_dp)
      guard%plain_theta2 = huge(1.0_dp)
      guard%res = huge(1.0_dp)
      guard%res_best = huge(1.0_dp)
      guard%growths = 0
      guard%mixing = .false.
      guard%restart = .false.
      guard%restarts = 0
      guard%mixing_from = 0
      guard%mixing_cause = fp_iterating
      guard%window_start = 1
      guard%ncol = 0
      guard%newest = 0
      guard%has_last = .false.
      if (allocated(guard%window)) then
         if (size(guard%window) /= max_iter) deallocate (guard%window)
      end if
      if (.not. allocated(guard%window)) allocate (guard%window(max_iter))
      if (allocated(guard%d_best)) then
         if (size(guard%d_best) /= n) deallocate (guard%d_best, guard%df, guard%dg, guard%f_last, guard%g_last)
      end if
      if (.not. allocated(guard%d_best)) allocate (guard%d_best(n), guard%df(n, anderson_depth), &
         guard%dg(n, anderson_depth), guard%f_last(n), guard%g_last(n))
   end subroutine fp_start

   !> Convergence is eq. (18) on the residual of the map,
   !>   sum (G(D) - D)^2 <= C_r2 sum (G(D) - D_t)^2,
   !> which is the paper's test for the plain iteration (there D^{n+1} = G(D^n)),
   !> or the residual at the rounding level of D (round_floor), below which no
   !> iteration can go. With guard%rate_test (scheme 'fast', src/scheme/fast_scheme.f90)
   !> G(D) is also accepted when eq. (18) holds for the change the next
   !> iteration would make, estimated with the contraction theta of the map:
   !>   theta^2 sum (G(D) - D)^2 <= C_r2 sum (G(D) - D_t)^2,
   !> theta^2 = guard%theta2_first (given by the caller) for the first
   !> iteration; from the third on the iteration's own, the larger of the last
   !> two quotients ratio(n)/ratio(n-1) (the contraction is not the same from
   !> one iteration to the next: the first removes the predictor's fast modes,
   !> and the ratios may alternate between a large and a small fall, so one
   !> quotient alone can promise far more than the next iteration gives); never
   !> for the second (its quotient is the first's: the paper's test decides);
   !> accelerated, from the fifth on the fourth's (the test bounds the error
   !> of G(D) by theta/(1 - theta) |G(D) - D|, theta the contraction of the
   !> map however D was found, and the falls of the mixed iterates are not
   !> the map's); never after the fall-back; and only while the ratio itself
   !> is below rate_test_max_ratio.
   !>
   !> Records the iteration D -> G(D): eq. (18), and the divergence and
   !> stagnation tests. Leaves state = fp_converged, fp_iterating (go on;
   !> the fall-back may just have been engaged), or the reason to stop.
   subroutine fp_check(guard, d, g, d_t)
      type(fp_guard_t), intent(inout) :: guard  !< guard
      real(dp), intent(in) :: d(:)              !< iterate D (m, rad)
      real(dp), intent(in) :: g(:)              !< its image G(D)
      real(dp), intent(in) :: d_t(:)            !< converged solution at t
      real(dp) :: num, den, theta2
      integer :: it, trouble
      logical :: mixed

      guard%iterations = guard%iterations + 1
      it = guard%iterations
      num = sum((g - d)**2)
      den = sum((g - d_t)**2)
      guard%res = num
      guard%ratios_before = [guard%ratios_before(2), guard%ratio]
      if (den > 0.0_dp) then
         guard%ratio = num/den
      else
         guard%ratio = merge(0.0_dp, huge(1.0_dp), num == 0.0_dp)
      end if
      guard%window(it) = num
      if (it == 1) guard%d_best = d
      mixed = guard%mixing .or. guard%accelerate

      ! -- eq. (18), or nothing left to gain above rounding
      if (ieee_is_finite(num) .and. ieee_is_finite(den)) then
         if (num <= guard%cr2*den .or. num <= round_floor*sum(g**2)) then
            guard%state = fp_converged
            return
         end if
      end if
      ! -- the rate test: eq. (18) on the estimated next change
      if (it <= first_mixed .or. .not. guard%accelerate) &
         guard%plain_theta2 = max(guard%ratio/guard%ratios_before(2), guard%ratios_before(2)/guard%ratios_before(1))
      if (guard%rate_test .and. .not. guard%mixing .and. guard%ratio <= rate_test_max_ratio .and. it /= 2) then
         theta2 = guard%theta2_first
         if (it >= 3) theta2 = guard%plain_theta2
         if (theta2 < 1.0_dp .and. theta2*guard%ratio <= guard%cr2) then
            guard%state = fp_converged
            return
         end if
      end if

      trouble = fp_iterating
      if (.not. (ieee_is_finite(num) .and. ieee_is_finite(den))) then
         trouble = fp_not_finite
      else if (.not. mixed) then
         ! -- the plain iteration: growth in a row, or too slow a fall
         if (it > guard%window_start .and. num > guard%window(it - 1)) then
            guard%growths = guard%growths + 1
         else
            guard%growths = 0
         end if
         if (guard%growths >= growth_limit) then
            trouble = fp_diverged
         else if (it - guard%window_start >= stagnation_window) then
            if (num > progress_factor*guard%window(it - stagnation_window)) trouble = fp_stagnated
         end if
      else
         ! -- the mixing, whose residual need not fall every iteration: a jump
         !    far above the best restarts it there; no new best by a factor
         !    progress_factor in mixing_window iterations is stagnation
         if (num > restart_factor*guard%res_best) then
            guard%restart = .true.
            guard%restarts = guard%restarts + 1
         end if
         if (it - guard%window_start >= mixing_window) then
            if (minval(guard%window(it - mixing_window + 1:it)) > &
                progress_factor*minval(guard%window(guard%window_start:it - mixing_window))) &
               trouble = merge(fp_diverged, fp_stagnated, guard%restarts > 0)
         end if
      end if
      if (ieee_is_finite(num) .and. num < guard%res_best) then
         guard%res_best = num
         guard%d_best = d
      end if

      if (trouble /= fp_iterating) then
         if (mixed) then
            guard%state = trouble                 ! the fall-back failed too, or the accelerated iteration
            return
         end if
         ! -- fall back to Anderson mixing, from the best iterate so far
         guard%mixing = .true.
         guard%restart = .true.
         guard%mixing_from = it
         guard%mixing_cause = trouble
         guard%window_start = it + 1
      end if
      if (it >= guard%max_iter) guard%state = fp_limit
   end subroutine fp_check

   !> With guard%accelerate (scheme 'fast', src/scheme/fast_scheme.f90) the
   !> mixing is not a fall-back but the iteration itself from its fifth
   !> iterate on: the first four are plain (most steps need no more, and
   !> they measure the plain map's contraction for the rate test below),
   !> every later one combines the iterates so far (Anderson acceleration).
   !> Where the deflection is large the plain map contracts slowly, and more
   !> slowly on finer meshes; accelerated, its iterations stay few
   !> (docs/PERFORMANCE.md, "Large deflections"). The mixing's own tests
   !> apply from the start; when they fail there is nothing further to fall
   !> back to, and the caller's sub-steps take over (src/scheme/substeps.f90).
   !>
   !> The next iterate: G(D) for the plain iteration of eq. (19); after the
   !> fall-back, Anderson mixing of the last iterates (the first mixing
   !> iterate is the best iterate so far); accelerated, plain up to the
   !> iteration first_mixed, then Anderson mixing of the iterates from the
   !> first on.
   subroutine fp_next(guard, d, g, stat, errmsg)
      type(fp_guard_t), intent(inout) :: guard  !< guard (mixing history)
      real(dp), intent(inout) :: d(:)           !< iterate in, next iterate out
      real(dp), intent(in) :: g(:)              !< G(D)
      integer, intent(out) :: stat              !< 0, or LAPACK's info
      character(len=*), intent(inout) :: errmsg !< reason on failure
      real(dp), allocatable :: a(:,:), b(:), work(:)
      real(dp) :: query(1)
      integer :: jpvt(anderson_depth), rank, info, m, n

      stat = 0
      if (.not. (guard%mixing .or. guard%accelerate)) then
         d = g
         return
      end if
      if (guard%restart) then
         ! -- just engaged, or a jump: restart from the best iterate, history cleared
         d = guard%d_best
         guard%restart = .false.
         guard%ncol = 0
         guard%newest = 0
         guard%has_last = .false.
         return
      end if

      ! -- Anderson mixing: the differences over the oldest in the ring (the
      !    least-squares problem does not depend on the columns' order), then
      !    the small least-squares problem
      n = size(d)
      if (guard%has_last) then
         guard%newest = modulo(guard%newest, anderson_depth) + 1
         guard%ncol = min(guard%ncol + 1, anderson_depth)
         guard%df(:, guard%newest) = (g - d) - guard%f_last
         guard%dg(:, guard%newest) = g - guard%g_last
      end if
      guard%f_last = g - d
      guard%g_last = g
      guard%has_last = .true.
      m = guard%ncol
      if (m == 0 .or. (.not. guard%mixing .and. guard%iterations < first_mixed)) then
         d = g
         return
      end if

      a = guard%df(:, 1:m)
      b = guard%f_last
      jpvt = 0
      call dgelsy(n, m, 1, a, n, b, n, jpvt, mixing_rcond, rank, query, -1, info)
      if (info /= 0) then
         stat = info
         write (errmsg, '(a,i0)') 'Anderson mixing: dgelsy workspace query failed, info = ', info
         return
      end if
      allocate (work(max(1, int(query(1)))))
      call dgelsy(n, m, 1, a, n, b, n, jpvt, mixing_rcond, rank, work, size(work), info)
      if (info /= 0) then
         stat = info
         write (errmsg, '(a,i0)') 'Anderson mixing: dgelsy failed, info = ', info
         return
      end if
      ! x_{k+1} = G(x_k) - dG gamma, gamma in b(1:m)
      d = g - matmul(guard%dg(:, 1:m), b(1:m))
   end subroutine fp_next

   !> What a state means, for messages.
   pure function fp_state_text(state) result(text)
      integer, intent(in) :: state              !< fp_* state
      character(len=:), allocatable :: text
      select case (state)
      case (fp_iterating)
         text = 'iterating'
      case (fp_converged)
         text = 'converged'
      case (fp_not_finite)
         text = 'the residual is not finite (NaN or Inf)'
      case (fp_diverged)
         text = 'diverging (the residual grew ' // int_str(growth_limit) // ' iterations in a row)'
      case (fp_stagnated)
         text = 'stagnating (the squared residual fell by less than a factor ' // &
            int_str(nint(1.0_dp/progress_factor)) // ' in ' // int_str(stagnation_window) // ' iterations)'
      case (fp_limit)
         text = 'iteration limit (max_nonlinear_iter) reached'
      case default
         text = 'unknown state'
      end select
   end function fp_state_text

   !> The diagnostic of a plate solution: how the iteration ended, its last
   !> eq. (18) ratio against C_r2, and the fall-back if it was engaged.
   function fp_report(guard) result(text)
      type(fp_guard_t), intent(in) :: guard     !< guard after the iteration
      character(len=:), allocatable :: text
      character(len=160) :: buf
      write (buf, '(a,i0,a,es10.3,a,es10.3,a,es10.3)') ' after ', guard%iterations, &
         ' iterations; eq. (18) ratio sum (G(D) - D)^2 / sum (G(D) - D_t)^2 = ', guard%ratio, &
         ' against C_r2 = ', guard%cr2, '; sum (G(D) - D)^2 = ', guard%res
      text = fp_state_text(guard%state) // trim(buf)
      if (guard%accelerate) text = text // '; Anderson-accelerated from iterate ' // int_str(first_mixed + 1) // &
                                   ' (scheme fast)'
      if (guard%mixing) text = text // '; the plain iteration had stopped at iteration ' // &
         int_str(guard%mixing_from) // ', ' // fp_state_text(guard%mixing_cause) // &
         ', and the fall-back (Anderson mixing) took over from there'
   end function fp_report


end module fixed_point
