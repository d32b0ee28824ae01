!> The Yang-Sun / Tan-Sun indentation law, eq. (11)-(13), with its
!> loading, unloading and reloading history.
!>
!>   loading    F = k alpha^1.5                                        eq. (11)
!>   unloading  F = F_m ((alpha - alpha_0)/(alpha_m - alpha_0))^q
!>   reloading  F = F_m ((alpha - alpha_0)/(alpha_m - alpha_0))^1.5
!>   alpha_0 = beta (alpha_m - alpha_p) if alpha_m > alpha_p, else 0    eq. (12)
!>   alpha = w_impactor - w_plate at the impact point                   eq. (13)
!>
!> F_m and alpha_m are the largest force and indentation reached so far
!> (F_m = k alpha_m^1.5), alpha_0 the permanent indentation.
!>
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
module contact_law
   use kinds, only: dp
   implicit none
   private
   public :: contact_law_t, contact_history_t, contact_force, contact_branch, &
             contact_commit, permanent_indentation, loading_indentation, &
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

   !> Contact force for the trial indentation alpha, eq. (11) and (12).
   elemental function contact_force(law, hist, alpha) result(f)
      type(contact_law_t), intent(in) :: law       !< law constants
      type(contact_history_t), intent(in) :: hist  !< committed history
      real(dp), intent(in) :: alpha                !< trial indentation (m)
      real(dp) :: f
      real(dp) :: ratio

      select case (contact_branch(hist, alpha))
      case (branch_loading)
         f = law%k*alpha**1.5_dp
      case (branch_unloading)
         ratio = (alpha - hist%alpha_0)/(hist%alpha_m - hist%alpha_0)
         f = hist%f_m*ratio**law%q
      case (branch_reloading)
         ratio = (alpha - hist%alpha_0)/(hist%alpha_m - hist%alpha_0)
         f = hist%f_m*ratio**1.5_dp
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

end module contact_law
