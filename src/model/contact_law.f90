!> The Yang-Sun / Tan-Sun indentation law, eq. (11)-(13), with its
!> loading, unloading and reloading history.
!>
!>   loading    F = k alpha^1.5                                        eq. (11)
!>   unloading  F = F_m ((alpha - alpha_0)/(alpha_m - alpha_0))^q
!>   reloading  F = F_m ((alpha - alpha_0)/(alpha_m - alpha_0))^1.5
!>   alpha_0 = beta (alpha_m - alpha_p) if alpha_m > alpha_p, else 0    eq. (12)
!>   alpha = w_impactor - w_plate at the impact point                   eq. (13)
!>
!> F_m and alpha_m are the largest force and indentation reached so far,
!> alpha_0 the permanent indentation. Which curve applies (the paper does
!> not say): above contact_branch. The history is committed once per
!> converged step (contact_commit); the contact iteration only reads it.
!> More: docs/MODEL.md.
module contact_law
   use kinds, only: dp
   implicit none
   private
   public :: contact_law_t, contact_history_t, contact_force, contact_branch, &
             contact_commit, permanent_indentation, loading_indentation, law_indentation, law_tangent, &
             solve_contact_equation, &
             branch_none, branch_loading, branch_unloading, branch_reloading

   !> Branches of the law (also written to the history file).
   integer, parameter :: branch_none = 0, branch_loading = 1, &
                         branch_unloading = 2, branch_reloading = 3

   !> The law's constants (paper Table 2, SI units).
   type :: contact_law_t
      real(dp) :: k = 1.413e9_dp        !< contact stiffness (N/m^1.5)
      real(dp) :: q = 2.5_dp            !< unloading exponent (-)
      real(dp) :: alpha_p = 1.667e-5_dp !< critical indentation (m)
      real(dp) :: beta = 0.094_dp       !< permanent indentation ratio (-)
   end type contact_law_t

   !> The committed history of the contact point.
   type :: contact_history_t
      real(dp) :: f_m = 0.0_dp       !< largest force so far, F_m (N)
      real(dp) :: alpha_m = 0.0_dp   !< largest indentation so far, alpha_m (m)
      real(dp) :: alpha_0 = 0.0_dp   !< permanent indentation, alpha_0 (m), eq. (12)
      logical :: separated = .false. !< unloaded to alpha_0 since the last maximum
   end type contact_history_t

contains

   !> Permanent indentation alpha_0 after a largest indentation alpha_m, eq. (12).
   elemental function permanent_indentation(law, alpha_m) result(alpha_0)
      type(contact_law_t), intent(in) :: law  !< law constants
      real(dp), intent(in) :: alpha_m         !< largest indentation (m)
      real(dp) :: alpha_0
      if (alpha_m > law%alpha_p) then
         alpha_0 = law%beta*(alpha_m - law%alpha_p)
      else
         alpha_0 = 0.0_dp
      end if
   end function permanent_indentation

   !> Indentation on the loading curve at force f: alpha = (f/k)^(2/3).
   elemental function loading_indentation(law, f) result(alpha)
      type(contact_law_t), intent(in) :: law  !< law constants
      real(dp), intent(in) :: f               !< force (N), >= 0
      real(dp) :: alpha
      alpha = (max(f, 0.0_dp)/law%k)**(2.0_dp/3.0_dp)
   end function loading_indentation

   !> The indentation at which the law gives the force f, on the curve a
   !> force f would follow after the committed history: the inverse of
   !> contact_force. Above F_m (or before any contact) the loading curve;
   !> below it the unloading curve, or the reloading curve once the impactor
   !> has left the plate (the switching rule above contact_branch). 0 for
   !> f <= 0. It gives the contact area of an assumed force (contact_load).
   elemental function law_indentation(law, hist, f) result(alpha)
      type(contact_law_t), intent(in) :: law       !< law constants
      type(contact_history_t), intent(in) :: hist  !< committed history
      real(dp), intent(in) :: f                    !< force (N)
      real(dp) :: alpha
      if (f <= 0.0_dp) then
         alpha = 0.0_dp
      else if (f >= hist%f_m .or. hist%alpha_m <= 0.0_dp) then
         alpha = loading_indentation(law, f)
      else if (hist%separated) then
         alpha = hist%alpha_0 + (hist%alpha_m - hist%alpha_0)*(f/hist%f_m)**(1.0_dp/1.5_dp)
      else
         alpha = hist%alpha_0 + (hist%alpha_m - hist%alpha_0)*(f/hist%f_m)**(1.0_dp/law%q)
      end if
   end function law_indentation

   !> The law's tangent stiffness dF/d alpha at the trial indentation alpha
   !> on the branch it follows (N/m), eq. (11)-(12) differentiated: loading
   !> 3/2 k alpha^1/2, unloading q F_m s^(q-1)/(alpha_m - alpha_0), reloading
   !> 3/2 F_m s^1/2/(alpha_m - alpha_0), s = (alpha - alpha_0)/(alpha_m -
   !> alpha_0); 0 out of contact.
   elemental function law_tangent(law, hist, alpha) result(k_t)
      type(contact_law_t), intent(in) :: law       !< law constants
      type(contact_history_t), intent(in) :: hist  !< committed history
      real(dp), intent(in) :: alpha                !< trial indentation (m)
      real(dp) :: k_t
      real(dp) :: span
      span = hist%alpha_m - hist%alpha_0
      select case (contact_branch(hist, alpha))
      case (branch_loading)
         k_t = 1.5_dp*law%k*sqrt(alpha)
      case (branch_unloading)
         k_t = law%q*hist%f_m*curve_ratio(hist, alpha)**(law%q - 1.0_dp)/span
      case (branch_reloading)
         k_t = 1.5_dp*hist%f_m*sqrt(curve_ratio(hist, alpha))/span
      case default
         k_t = 0.0_dp
      end select
   end function law_tangent

   !> Which curve applies (the paper gives the three curves, not the switching
   !> rule; this is the rule used here, chosen so that F(alpha) is continuous
   !> and the law never creates energy):
   !>  - alpha >= alpha_m: the loading curve (a new maximum);
   !>  - below alpha_m after a maximum: the unloading curve, both ways (a partial
   !>    unload that turns back retraces it elastically);
   !>  - once the unloading has reached alpha_0 (the impactor has left the
   !>    plate), the next contact follows the reloading curve up to alpha_m, and
   !>    beyond alpha_m the loading curve again.
   !> All three curves give F = 0 for alpha <= alpha_0 (no tension).
   !>
   !> The history is committed once per converged time step (contact_commit);
   !> contact_force evaluates a trial indentation against the committed
   !> history, so the contact iteration of a step never changes the history.
   !>
   !> The branch of the law that a trial indentation alpha follows.
   elemental function contact_branch(hist, alpha) result(branch)
      type(contact_history_t), intent(in) :: hist  !< committed history
      real(dp), intent(in) :: alpha                !< trial indentation (m)
      integer :: branch
      if (alpha <= 0.0_dp) then
         branch = branch_none
      else if (alpha >= hist%alpha_m) then
         branch = branch_loading
      else if (alpha <= hist%alpha_0) then
         branch = branch_none
      else if (hist%separated) then
         branch = branch_reloading
      else
         branch = branch_unloading
      end if
   end function contact_branch

   !> s = (alpha - alpha_0)/(alpha_m - alpha_0), the argument of the
   !> unloading and reloading curves, eq. (11), at a trial indentation alpha
   !> between alpha_0 and alpha_m.
   elemental function curve_ratio(hist, alpha) result(s)
      type(contact_history_t), intent(in) :: hist  !< committed history
      real(dp), intent(in) :: alpha                !< trial indentation (m)
      real(dp) :: s
      s = (alpha - hist%alpha_0)/(hist%alpha_m - hist%alpha_0)
   end function curve_ratio

   !> Contact force for the trial indentation alpha, eq. (11) and (12).
   elemental function contact_force(law, hist, alpha) result(f)
      type(contact_law_t), intent(in) :: law       !< law constants
      type(contact_history_t), intent(in) :: hist  !< committed history
      real(dp), intent(in) :: alpha                !< trial indentation (m)
      real(dp) :: f

      select case (contact_branch(hist, alpha))
      case (branch_loading)
         f = law%k*alpha**1.5_dp
      case (branch_unloading)
         f = hist%f_m*curve_ratio(hist, alpha)**law%q
      case (branch_reloading)
         f = hist%f_m*curve_ratio(hist, alpha)**1.5_dp
      case default
         f = 0.0_dp
      end select
   end function contact_force

   !> Commits the converged indentation of a time step to the history.
   elemental subroutine contact_commit(law, hist, alpha)
      type(contact_law_t), intent(in) :: law          !< law constants
      type(contact_history_t), intent(inout) :: hist  !< history, updated
      real(dp), intent(in) :: alpha                   !< converged indentation (m)
      if (alpha > 0.0_dp .and. alpha >= hist%alpha_m) then
         hist%alpha_m = alpha
         hist%f_m = law%k*alpha**1.5_dp
         hist%alpha_0 = permanent_indentation(law, alpha)
         hist%separated = .false.
      else if (alpha <= hist%alpha_0 .and. hist%alpha_m > 0.0_dp) then
         hist%separated = .true.
      end if
   end subroutine contact_commit

   !> The contact equation of a time step when the indentation depends
   !> linearly on the force, alpha(F) = alpha_free - compliance F:
   !>     F = F_law(alpha_free - compliance F)                  eq. (11)-(13)
   !> (used by scheme = 'fast': within one nonlinear iteration the plate's
   !> deflection at the impact point and the impactor's position, eq. 21, are
   !> both linear in F). F - F_law(alpha(F)) increases with F, is <= 0 at
   !> F = 0 and >= 0 at F = F_law(alpha_free), so the root is bracketed and
   !> regula falsi with the Illinois modification finds it to rounding.
   pure subroutine solve_contact_equation(law, hist, alpha_free, compliance, f, alpha)
      type(contact_law_t), intent(in) :: law       !< law constants
      type(contact_history_t), intent(in) :: hist  !< committed history
      real(dp), intent(in) :: alpha_free           !< indentation at F = 0 (m)
      real(dp), intent(in) :: compliance           !< d alpha / d F, negated (m/N), > 0
      real(dp), intent(out) :: f                   !< contact force (N)
      real(dp), intent(out) :: alpha               !< indentation at that force (m)
      integer, parameter :: max_iter = 200
      real(dp), parameter :: rel_tol = 1.0e-13_dp
      real(dp) :: lo, hi, r_lo, r_hi, r
      integer :: it, side

      f = 0.0_dp
      alpha = alpha_free
      hi = contact_force(law, hist, alpha_free)
      if (hi <= 0.0_dp) return                       ! no contact even if the plate gave way
      lo = 0.0_dp;  r_lo = -hi
      r_hi = hi - contact_force(law, hist, alpha_free - compliance*hi)
      if (r_hi <= 0.0_dp) then                       ! the law's force cannot be reduced: a rigid plate
         f = hi;  alpha = alpha_free - compliance*hi
         return
      end if
      side = 0
      illinois: do it = 1, max_iter
         f = lo - r_lo*(hi - lo)/(r_hi - r_lo)
         r = f - contact_force(law, hist, alpha_free - compliance*f)
         if (r > 0.0_dp) then
            hi = f;  r_hi = r
            if (side == 1) r_lo = 0.5_dp*r_lo
            side = 1
         else if (r < 0.0_dp) then
            lo = f;  r_lo = r
            if (side == -1) r_hi = 0.5_dp*r_hi
            side = -1
         else
            exit illinois
         end if
         if (hi - lo <= rel_tol*hi) exit illinois
      end do illinois
      alpha = alpha_free - compliance*f
   end subroutine solve_contact_equation

end module contact_law
