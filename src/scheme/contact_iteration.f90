!> The contact-force iteration of a time step (Fig. 3, the outer loop):
!> assume a contact force, solve the plate under it (src/scheme/plate_solver.f90),
!> move the impactor (eq. 21), compute the indentation (eq. 13) and the
!> law's force (eq. 11-12), and repeat with a new assumed force until the
!> two agree (eq. 17). How the assumed force is updated (the paper does
!> not say; &analysis force_update): above force_bracket_t.
!> The contact area belongs to the assumed force (module contact_load): a
!> disc of radius sqrt(R alpha(F)), alpha(F) the law's indentation at F.
!> More: docs/ALGORITHM.md.
module contact_iteration
   use kinds, only: dp
   use plate_model, only: model_t
   use newmark, only: newmark_t, plate_state_t, impactor_t, impactor_moved, newmark_update
   use contact_law, only: contact_history_t, contact_force, law_indentation, contact_commit
   use contact_load, only: load_pattern_t, load_pattern, load_hertz, pattern_mean
   implicit none
   private
   public :: step_state_t, step_start, step_accept, contact_iteration_t, force_bracket_t, contact_start, &
             contact_next, contact_cut, contact_area, &
             contact_indentation, contact_converged, contact_outcome, contact_report, bracket_update

   !> The paper does not say how the assumed force is updated (§2.3 reads as
   !> the plain fixed point F_assum <- F_cont). &analysis force_update:
   !>  - 'bracketed' (the default): the residual r(F) = F - F_cont(F) grows with
   !>    F (a harder push stops the impactor sooner and deflects the plate
   !>    more), so the root is bracketed: the law's force is taken until it is,
   !>    then regula falsi with the Illinois modification. It always converges.
   !>  - 'fixed_point': F <- F_cont while |r| falls by at least max_contraction
   !>    per iteration, then the bracketed update (a fall-back, warned).
   !>  - 'plain': F <- F_cont and nothing else, the paper's words; a step that
   !>    does not meet eq. (17) in max_contact_iter iterations keeps its last
   !>    force and the run goes on (counted; docs/PAPER.md "Time step and
   !>    divergence" shows where it diverges, and why).
   !>
   !> The contact iteration's knowledge of the root of r(F) = F - F_cont(F).
   type :: force_bracket_t
      real(dp) :: lo = 0.0_dp, hi = huge(1.0_dp)  !< bracket (N)
      real(dp) :: r_lo = 0.0_dp, r_hi = 0.0_dp    !< residuals at the ends
      logical :: has_lo = .false., has_hi = .false.  !< residual known at that end
      integer :: last_side = 0                    !< end moved last (-1 lo, +1 hi), for Illinois
      logical :: blind_hi = .false.      !< hi is a force whose plate solution failed: no residual there
      real(dp) :: r_prev = huge(1.0_dp)  !< |r| of the previous iteration (N)
   end type force_bracket_t

   !> One step's contact iteration.
   type :: contact_iteration_t
      character(len=16) :: update = 'bracketed'   !< &analysis force_update (set once, before the steps)
      real(dp) :: cr1 = 0.002_dp      !< C_r1 of eq. (17) (&analysis cr1; set once, before the steps)
      integer :: iterations = 0       !< iterations made in this step (plate solutions tried)
      logical :: solved = .false.     !< the last plate solution (eq. 19) converged
      logical :: converged = .false.  !< eq. (17) was met
      real(dp) :: f_assum = 0.0_dp    !< the assumed contact force on the whole plate (N)
      real(dp) :: f_cont = 0.0_dp     !< the law's force at the indentation it gave (N)
      real(dp) :: alpha = 0.0_dp      !< that indentation, eq. (13) (m)
      type(load_pattern_t) :: pattern !< the contact area of f_assum (module contact_load)
      type(force_bracket_t) :: br     !< the bracket of the root
      logical :: fell_back = .false.  !< 'fixed_point' stopped contracting: bracketed from then on
      logical :: cut = .false.        !< a plate solution failed under an assumed force, which was cut
   end type contact_iteration_t

   !> The state of a time step (Fig. 3): the plate and the impactor at t, the
   !> contact's committed history, the step's contact iteration, and what the
   !> step computes, M {b} of eq. (19)-(20) and the plate and impactor at t+dt.
   type :: step_state_t
      type(plate_state_t) :: plate          !< {D}, {V}, {A} at t
      type(impactor_t) :: imp               !< the impactor (mass; position, velocity, force) at t
      type(contact_history_t) :: hist       !< the contact's committed history (eq. 11-12)
      type(contact_iteration_t) :: cit      !< the step's contact iteration (eq. 17)
      real(dp), allocatable :: mb(:)        !< M {b} of eq. (19)-(20), fixed within the step
      real(dp), allocatable :: d_new(:)     !< {D} at t+dt, the iterate of eq. (19)
      type(impactor_t) :: imp_new           !< the impactor at t+dt under the step's force
   end type step_state_t

   !> Smallest factor by which the law's force must shrink the contact
   !> residual per iteration (0.5: C_r1 = 0.2 % from a residual of the order
   !> of the force within about 9 iterations); below it force_update =
   !> 'fixed_point' falls back to the bracketed update, and the bracketed
   !> update, with only an upper end known, tries F = 0.
   real(dp), parameter :: max_contraction = 0.5_dp
   !> A force below this fraction of the largest the contact has had is zero
   !> to it (contact_converged).
   real(dp), parameter :: negligible_force = 1.0e-9_dp

contains

   !> The state at t = 0: the plate at rest, the impactor imp touching it,
   !> the contact's history fresh and its area that of imp's force.
   subroutine step_start(st, model, imp, cit)
      type(step_state_t), intent(out) :: st         !< the state
      type(model_t), intent(in) :: model            !< the model
      type(impactor_t), intent(in) :: imp           !< the impactor at t = 0
      type(contact_iteration_t), intent(in) :: cit  !< the contact iteration with its settings (update, cr1)
      integer :: neq
      neq = model%msh%neq
      allocate (st%plate%d(neq), st%plate%v(neq), st%plate%a(neq), source=0.0_dp)
      allocate (st%mb(neq), st%d_new(neq))
      st%imp = imp
      st%cit = cit
      call contact_area(model, st%hist, imp%f, st%cit%pattern)
   end subroutine step_start

   !> Accepts the step with the constants nm: Newmark's update (eq. 20), the
   !> impactor at t+dt; with commit, the contact history too.
   subroutine step_accept(st, nm, model, commit)
      type(step_state_t), intent(inout) :: st       !< the step: its state at t becomes that at t+dt
      type(newmark_t), intent(in) :: nm             !< Newmark constants of the step
      type(model_t), intent(in) :: model            !< the model (its contact law)
      logical, intent(in) :: commit                 !< commit the contact history (eq. 12)
      call newmark_update(nm, st%plate%d, st%d_new, st%plate%v, st%plate%a)
      st%plate%d = st%d_new
      st%imp = st%imp_new
      if (commit) call contact_commit(model%law, st%hist, st%cit%alpha)
   end subroutine step_accept

   !> The first assumed force of a step (§2.3): the impactor indents as if the
   !> plate did not react, w_plate staying at its value at t and the impactor
   !> moving on under the force of t alone; and its contact area.
   subroutine contact_start(cit, model, hist, nm, imp, w_plate)
      type(contact_iteration_t), intent(inout) :: cit  !< the step's iteration (its pattern kept: a cache)
      type(model_t), intent(in) :: model             !< model (law, contact load)
      type(contact_history_t), intent(in) :: hist    !< committed contact history
      type(newmark_t), intent(in) :: nm              !< Newmark constants (the step dt)
      type(impactor_t), intent(in) :: imp            !< impactor at t
      real(dp), intent(in) :: w_plate                !< plate deflection under the impactor at t (m)
      type(impactor_t) :: imp_free
      ! a fresh iteration but for the pattern, whose polynomials serve while the
      ! contact radius stays in their interval (src/model/contact_load.f90)
      cit%iterations = 0;  cit%solved = .false.;  cit%converged = .false.
      cit%f_cont = 0.0_dp;  cit%alpha = 0.0_dp
      cit%br = force_bracket_t()
      cit%fell_back = .false.;  cit%cut = .false.
      imp_free = impactor_moved(nm, imp, 0.0_dp)      ! eq. (21) under the force of t alone
      cit%f_assum = contact_force(model%law, hist, imp_free%w - w_plate)
      call contact_area(model, hist, cit%f_assum, cit%pattern)
   end subroutine contact_start

   !> The indentation of the moved impactor into the plate solved under
   !> f_assum, eq. (13), and the law's force at it, eq. (11)-(12); then the
   !> test of eq. (17) (contact_converged) on the two forces.
   subroutine contact_indentation(cit, model, hist, imp_new, d_new)
      type(contact_iteration_t), intent(inout) :: cit  !< the iteration: alpha, f_cont, converged out
      type(model_t), intent(in) :: model               !< model (law)
      type(contact_history_t), intent(in) :: hist      !< committed contact history
      type(impactor_t), intent(in) :: imp_new          !< the impactor at t+dt under f_assum
      real(dp), intent(in) :: d_new(:)                 !< the plate at t+dt under f_assum
      cit%alpha = imp_new%w - pattern_mean(cit%pattern, d_new)
      cit%f_cont = contact_force(model%law, hist, cit%alpha)
      cit%converged = contact_converged(cit%f_assum, cit%f_cont, cit%cr1, hist%f_m)
   end subroutine contact_indentation

   !> The step's outcome after the contact loop: accepted when eq. (17) was
   !> met. With force_update = 'plain' (the paper's words, above force_bracket_t) a
   !> step that did not meet it but whose plate was solved is accepted all
   !> the same with the law's last force, F_assum <- F_cont, as the
   !> impactor's force at t+dt (counted as unconverged in the summary). Any
   !> other step is not accepted: the run stops with contact_report.
   pure subroutine contact_outcome(cit, imp_new, accepted)
      type(contact_iteration_t), intent(in) :: cit   !< the iteration at its end
      type(impactor_t), intent(inout) :: imp_new     !< the impactor at t+dt: its force set for 'plain'
      logical, intent(out) :: accepted               !< the step is accepted
      accepted = cit%converged .or. (cit%update == 'plain' .and. cit%solved)
      if (accepted .and. .not. cit%converged) imp_new%f = cit%f_cont
   end subroutine contact_outcome

   !> The next assumed force after an iteration that did not meet eq. (17)
   !> (above force_bracket_t: force_update), and its contact area.
   subroutine contact_next(cit, model, hist)
      type(contact_iteration_t), intent(inout) :: cit  !< the iteration: f_assum, f_cont of the last
      type(model_t), intent(in) :: model               !< model
      type(contact_history_t), intent(in) :: hist      !< committed contact history
      real(dp) :: f_next
      logical :: contracting
      if (cit%update == 'plain') then
         f_next = cit%f_cont
      else
         contracting = abs(cit%f_assum - cit%f_cont) <= max_contraction*cit%br%r_prev
         call bracket_update(cit%br, cit%f_assum, cit%f_cont, f_next)
         if (cit%update == 'fixed_point' .and. .not. cit%fell_back) then
            if (contracting) then
               f_next = cit%f_cont
            else
               cit%fell_back = .true.
            end if
         end if
      end if
      cit%f_assum = f_next
      call contact_area(model, hist, cit%f_assum, cit%pattern)
   end subroutine contact_next

   !> The plate solution under f_assum failed (eq. 19 did not converge, even
   !> with its fall-back): the force is taken as too high (a harder push
   !> deflects the plate more, and large deflections break eq. 19); it
   !> becomes the upper end of the bracket, without a residual, and the next
   !> assumed force is the middle of the bracket.
   subroutine contact_cut(cit, model, hist)
      type(contact_iteration_t), intent(inout) :: cit  !< the iteration
      type(model_t), intent(in) :: model               !< model
      type(contact_history_t), intent(in) :: hist      !< committed contact history
      cit%cut = .true.
      cit%br%hi = cit%f_assum;  cit%br%has_hi = .true.;  cit%br%blind_hi = .true.;  cit%br%last_side = 1
      cit%f_assum = 0.5_dp*(cit%br%lo + cit%br%hi)
      call contact_area(model, hist, cit%f_assum, cit%pattern)
   end subroutine contact_cut

   !> The contact area of the contact force f (N): the pattern of its load
   !> (module contact_load), with the contact radius a = sqrt(R alpha(f)),
   !> alpha(f) the law's indentation at f after the committed history.
   pure subroutine contact_area(model, hist, f, pattern)
      type(model_t), intent(in) :: model             !< model
      type(contact_history_t), intent(in) :: hist    !< committed contact history
      real(dp), intent(in) :: f                      !< contact force on the whole plate (N)
      type(load_pattern_t), intent(inout) :: pattern !< its load pattern
      real(dp) :: a
      a = 0.0_dp
      if (model%cload%kind == load_hertz .and. f > 0.0_dp) &
         a = sqrt(model%cload%nose_radius*law_indentation(model%law, hist, f))
      call load_pattern(model%cload, model%msh, a, pattern)
   end subroutine contact_area

   !> Records the residual r = f_assumed - f_contact and returns the next
   !> assumed force: the law's force while only one side of the root is
   !> known, regula falsi with the Illinois modification once it is
   !> bracketed. It always converges because r increases with the force.
   !> Only forces too high known, and the law's force no longer shrinking
   !> |r| by max_contraction (a plate that yields almost as much as the law
   !> asks: thin plates, light contacts, where the fixed point would crawl
   !> towards 0 for hundreds of iterations): F = 0 is tried; its residual
   !> -F_cont(0) <= 0 closes the bracket, or F_cont(0) = 0 is the root.
   pure subroutine bracket_update(br, f_assumed, f_contact, f_next)
      type(force_bracket_t), intent(inout) :: br  !< bracket, updated
      real(dp), intent(in) :: f_assumed           !< force the plate was solved with (N)
      real(dp), intent(in) :: f_contact           !< force of the law at the resulting indentation (N)
      real(dp), intent(out) :: f_next             !< next assumed force (N)
      real(dp) :: r
      logical :: inside
      r = f_assumed - f_contact
      if (r > 0.0_dp) then
         if (br%last_side == 1 .and. br%has_lo) br%r_lo = 0.5_dp*br%r_lo   ! Illinois
         br%hi = f_assumed;  br%r_hi = r;  br%has_hi = .true.;  br%last_side = 1
      else
         if (br%last_side == -1 .and. br%has_hi) br%r_hi = 0.5_dp*br%r_hi
         br%lo = f_assumed;  br%r_lo = r;  br%has_lo = .true.;  br%last_side = -1
      end if
      if (r > 0.0_dp) br%blind_hi = .false.
      if (br%has_lo .and. br%has_hi .and. .not. br%blind_hi) then
         f_next = br%lo - br%r_lo*(br%hi - br%lo)/(br%r_hi - br%r_lo)
      else if (br%has_hi .and. .not. br%has_lo .and. abs(r) > max_contraction*br%r_prev) then
         f_next = br%lo        ! F = 0: either the root (no contact) or the bracket's lower end
      else
         f_next = f_contact
      end if
      br%r_prev = abs(r)
      ! stay inside the bracket; F = 0 may be tried while its residual is unknown
      inside = f_next < br%hi .and. (f_next > br%lo .or. (.not. br%has_lo .and. f_next >= br%lo))
      if (.not. inside) then
         if (br%has_hi) then
            f_next = 0.5_dp*(br%lo + br%hi)
         else
            f_next = max(f_contact, br%lo)
         end if
      end if
   end subroutine bracket_update

   !> Convergence of the contact iteration, eq. (17):
   !> |F_assum - F_cont| / F_assum < C_r1 (both zero: no contact, converged),
   !> or a difference below C_r1 negligible_force f_m, f_m the largest force
   !> the contact has had (contact_history_t): as the impactor leaves the
   !> plate the root can be a force at the level of rounding (1e-14 N after
   !> a 300 N contact), which the relative test never accepts; for every
   !> force above that level the test is the paper's.
   pure function contact_converged(f_assumed, f_contact, cr1, f_m) result(done)
      real(dp), intent(in) :: f_assumed, f_contact  !< forces (N)
      real(dp), intent(in) :: cr1                   !< tolerance C_r1
      real(dp), intent(in) :: f_m                   !< largest force of the contact so far (N)
      logical :: done
      if (f_assumed <= 0.0_dp) then
         done = f_contact <= 0.0_dp
      else
         done = abs(f_assumed - f_contact) < cr1*max(f_assumed, negligible_force*f_m)
      end if
   end function contact_converged

   !> The diagnostic of a contact iteration that did not converge: the last
   !> forces, their eq. (17) residual against C_r1, and the bracket.
   function contact_report(cit) result(text)
      type(contact_iteration_t), intent(in) :: cit  !< the iteration at its end
      character(len=:), allocatable :: text
      character(len=320) :: buf
      real(dp), parameter :: collapsed = 1.0e-9_dp   ! relative width of a bracket that has collapsed
      write (buf, '(a,i0,a,es12.5,a,es12.5,a,es10.3,a,es10.3,a,es16.9,a,es16.9,a)') 'no convergence in ', &
         cit%iterations, ' iterations (max_contact_iter); F_assum = ', cit%f_assum, ' N, F_cont = ', cit%f_cont, &
         ' N, |F_assum - F_cont| / F_assum = ', abs(cit%f_assum - cit%f_cont)/max(abs(cit%f_assum), tiny(1.0_dp)), &
         ' against C_r1 = ', cit%cr1, '; the root lies in [', cit%br%lo, ', ', min(cit%br%hi, huge(1.0_dp)), '] N'
      text = trim(buf)
      if (cit%br%blind_hi) then
         text = text // '; the plate solution (eq. 19) failed under the upper end of the bracket, and the ' // &
            'root lies beyond the forces it can be solved for with this time step: a shorter dt may help'
      else if (cit%br%has_lo .and. cit%br%has_hi .and. cit%br%hi - cit%br%lo <= collapsed*cit%br%hi) then
         text = text // '; the bracket has shrunk to a point where F_cont jumps (the plate''s response ' // &
            'changes abruptly there)'
      end if
   end function contact_report

end module contact_iteration
