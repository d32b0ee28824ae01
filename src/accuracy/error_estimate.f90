!> The discretisation error of a result from a ladder of runs that differ in one parameter
!> (dt, or the element size). From the last three levels the observed order p solves
!> (h1^p - h2^p)/(h2^p - h3^p) = d1/d2: in range, Richardson's error at min(p, the method's
!> order) times richardson_safety; monotone but slower, Richardson's at p (at most slow_cap
!> times the larger difference), no less than the safe bound; otherwise the safe bound,
!> safe_factor times the larger difference, never an extrapolation. Two levels:
!> two_level_factor |d| (Roache's Fs = 3); one level: huge. A floor is added.
module error_estimate
   use kinds, only: dp
   implicit none
   private
   public :: estimate_t, ladder_estimate, observed_order, log_tail, two_grid_index, continued_value
   public :: safe_factor, last_difference

   !> Factors of safety (module header) (-).
   real(dp), parameter :: richardson_safety = 1.25_dp, safe_factor = 1.5_dp, two_level_factor = 3.0_dp, &
      slow_cap = 5.0_dp
   !> Orders the bisection of observed_order looks within (-).
   real(dp), parameter :: order_min = 0.05_dp, order_max = 12.0_dp

   !> The estimate of one result on one ladder.
   type :: estimate_t
      real(dp) :: error = huge(1.0_dp)     !< bound on |q(finest) - q(h -> 0)|, the result's unit
      real(dp) :: order = -1.0_dp          !< observed order, -1 when there is none
      logical :: asymptotic = .false.      !< the order is in the asymptotic range
      character(len=40) :: how = ''        !< which rule gave the error
      real(dp) :: floor = 0.0_dp           !< of which the resolution floor
   end type estimate_t

contains

   !> The error of the finest level of a ladder (module header).
   pure function ladder_estimate(h, q, order_theory, order_low, order_high, floor) result(e)
      real(dp), intent(in) :: h(:), q(:)       !< step or element size of each level, decreasing; the result at each
      real(dp), intent(in) :: order_theory     !< the method's order: no larger order is used
      real(dp), intent(in) :: order_low, order_high   !< the asymptotic range of orders
      real(dp), intent(in) :: floor            !< resolution added to the error (0: none)
      type(estimate_t) :: e
      real(dp) :: d1, d2, p, safe
      integer :: n
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
         p = observed_order(h(n - 2:n), d1/d2)
         e%order = p
         e%asymptotic = p >= order_low .and. p <= order_high
         if (e%asymptotic) then
            e%error = richardson_safety*richardson(min(p, order_theory)) + floor
            e%how = 'Richardson, order in range'
         else if (p < order_low) then
            e%error = max(min(richardson_safety*richardson(p), slow_cap*max(abs(d1), abs(d2))), safe) + floor
            e%how = 'slow: Richardson at observed order'
         else
            e%error = safe + floor
            e%how = 'order too high: 1.5 x largest diff.'
         end if
      end if
   contains
      !> Richardson's error of the finest level at order po.
      pure real(dp) function richardson(po)
         real(dp), intent(in) :: po
         real(dp) :: ratio
         ratio = (h(n)/h(n - 1))**po
         richardson = huge(1.0_dp)
         if (ratio < 1.0_dp) richardson = abs(d2)*ratio/(1.0_dp - ratio)
      end function richardson
   end function ladder_estimate

   !> The order p of (h1^p - h2^p)/(h2^p - h3^p) = ratio > 0 by bisection in [order_min, order_max].
   pure real(dp) function observed_order(h, ratio) result(p)
      real(dp), intent(in) :: h(3)           !< the three sizes, decreasing
      real(dp), intent(in) :: ratio          !< d1/d2, positive
      real(dp) :: lo, hi
      integer :: it
      lo = order_min;  hi = order_max
      p = merge(lo, hi, ratio <= f(lo))
      if (ratio <= f(lo) .or. ratio >= f(hi)) return
      do it = 1, 100
         p = 0.5_dp*(lo + hi)
         if (f(p) < ratio) lo = p
         if (f(p) >= ratio) hi = p
      end do
      p = 0.5_dp*(lo + hi)
   contains
      !> (h1^x - h2^x)/(h2^x - h3^x), scaled by h3 (it grows with x).
      pure real(dp) function f(x)
         real(dp), intent(in) :: x
         f = ((h(1)/h(3))**x - (h(2)/h(3))**x)/((h(2)/h(3))**x - 1.0_dp)
      end function f
   end function observed_order

   !> The change still to come, like ln(1/h), on a mesh that does not resolve a length (the
   !> Hertz disc): 0 when it does (size_ratio <= 1) or with fewer than two levels.
   pure real(dp) function log_tail(h, q, size_ratio)
      real(dp), intent(in) :: h(:), q(:)       !< element size of each level, decreasing; the result at each
      real(dp), intent(in) :: size_ratio       !< the finest level's element over the length (s/a)
      integer :: n
      n = size(q)
      log_tail = 0.0_dp
      if (n < 2 .or. size_ratio <= 1.0_dp) return
      log_tail = last_difference(q)*(log(size_ratio)/log(h(n - 1)/h(n)) + 1.0_dp)
   end function log_tail

   !> The larger of the last two differences of a ladder.
   pure real(dp) function last_difference(q)
      real(dp), intent(in) :: q(:)                !< the result at each level
      integer :: n
      n = size(q)
      last_difference = max(0.0_dp, maxval(abs(q(max(1, n - 2):n - 1) - q(max(2, n - 1):n))))
   end function last_difference

   !> Roache's grid convergence index of the finer of two levels of known order p.
   pure real(dp) function two_grid_index(h, q, p) result(e)
      real(dp), intent(in) :: h(2), q(2)       !< step or element size of the two levels, decreasing; the result at each
      real(dp), intent(in) :: p
      e = two_level_factor*abs(q(1) - q(2))/((h(1)/h(2))**p - 1.0_dp)
   end function two_grid_index

   !> The value of the next level of a ladder that goes on converging at order p.
   pure real(dp) function continued_value(h, q, p) result(q_next)
      real(dp), intent(in) :: h(3), q(2)       !< sizes of the last two levels and the next; the results of the two
      real(dp), intent(in) :: p
      q_next = q(2) - (q(1) - q(2))*(h(3)**p - h(2)**p)/(h(2)**p - h(1)**p)
   end function continued_value

end module error_estimate
