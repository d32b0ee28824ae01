!> Static analysis (`&analysis kind = 'static'`): the plate under the load of `&load`, linear
!> or with von Karman large deflection. Linear theory: K_L D = F, one Cholesky factorisation of
!> K_L. Nonlinear theory: Newton's method in `&load increments` equal load increments (why not
!> Akay's iteration: above static_solve). In increment i (load factor lambda = i/n):
!>     K_T(D^k) dD = lambda F - f_int(D^k),   D^{k+1} = D^k + dD,
!> f_int(D) = K_L D + K_N(D) D (eq. 15) and K_T its exact derivative, until the eq. (18)
!> measure sum dD^2 <= C_r2 sum (D^{k+1} - D_{i-1})^2. More: docs/ANALYSES.md.
module static_analysis
   use number_text, only: int_str, real_str
   use kinds, only: dp
   use plate_model, only: model_t, nonlinear_force, centre_deflection, gather_element
   use element_matrices, only: element_tangent_stiffness
   use global_matrix, only: global_matrix_t, global_init, global_zero, global_assemble, global_copy, &
      global_matvec, global_factor, global_solve, global_release
   use mesh, only: nfe, describe_equation
   implicit none
   private
   public :: static_result_t, static_solve

   !> The load-deflection path of a static analysis.
   type :: static_result_t
      integer :: increments = 0                 !< load increments completed
      real(dp), allocatable :: load_factor(:)   !< (0:n) load factor lambda (-)
      real(dp), allocatable :: w_centre(:)      !< (0:n) centre deflection (m)
      integer, allocatable :: iterations(:)     !< (0:n) Newton iterations (linear: 1)
      real(dp), allocatable :: residual(:)      !< (0:n) |lambda F - f_int| / |lambda F| at the end (-)
      real(dp), allocatable :: d(:)             !< displacements at the last load completed (m, rad)
   end type static_result_t

contains

   !> Why Newton and not Akay's fixed-point iteration: in a time step 4/dt^2 M dominates K_N
   !> and the iteration contracts; in statics, once w ~ h, K_N exceeds K_L and D <- K_L^-1 (F -
   !> K_N(D) D) diverges. Newton converges there, for a factorisation of K_T per iteration.
   !>
   !> The plate under the loads lambda_i F, lambda_i = i/increments: linear
   !> (one solve, scaled) or Newton in each increment (module header).
   !> On failure res holds the increments completed.
   subroutine static_solve(model, f, increments, res, stat, errmsg)
      type(model_t), intent(in) :: model            !< model
      real(dp), intent(in) :: f(:)                  !< load vector at load factor 1 (N)
      integer, intent(in) :: increments             !< load increments (>= 1)
      type(static_result_t), intent(out) :: res     !< load-deflection path
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      type(global_matrix_t) :: kl, kt
      real(dp) :: d(size(f)), d_start(size(f)), r(size(f)), fint(size(f)), lam, num, den
      real(dp) :: ke(nfe, nfe), de(nfe), d_unit(size(f))
      integer :: inc, it, bad_eq, e
      allocate (res%load_factor(0:increments), res%w_centre(0:increments), res%residual(0:increments), source=0.0_dp)
      allocate (res%iterations(0:increments), source=0)
      d = 0.0_dp
      res%d = d

      if (model%nonlinear) then
         call global_init(kt, model%stiff%storage, model%msh%neq, model%msh%elem_eq, stat, errmsg)
      else
         ! -- linear theory: K_L D = F once, then the path is linear in lambda
         call global_copy(kl, model%stiff)
         call global_factor(kl, stat, errmsg, bad_eq)
         if (stat /= 0 .and. bad_eq > 0) errmsg = 'static: K_L is not positive definite ' // &
            '(a mechanism: check &boundary): pivot of ' // trim(describe_equation(model%msh, bad_eq))
         if (stat /= 0) return
         d_unit = f
         call global_solve(kl, d_unit, stat, errmsg)
         call global_release(kl)                         ! sparse: CHOLMOD's factor, C memory
      end if
      if (stat /= 0) return
      load_increments: do inc = 1, increments
         lam = real(inc, dp)/real(increments, dp)
         if (.not. model%nonlinear) then
            d = lam*d_unit
            it = 1
         else
            ! -- von Karman theory: Newton in every load increment
            d_start = d
            newton_iterations: do it = 1, model%max_nonlinear_iter
               call internal_force(model, d, fint)
               r = lam*f - fint
               call global_zero(kt)                    ! K_T(D), assembled and factored
               elements: do e = 1, model%msh%nelem
                  call gather_element(model%msh%elem_eq(:, e), d, de)
                  call element_tangent_stiffness(model%lmt, model%geo(e), de, ke)
                  call global_assemble(kt, ke, model%msh%elem_eq(:, e))
               end do elements
               call global_factor(kt, stat, errmsg, bad_eq)
               if (stat /= 0 .and. bad_eq > 0) errmsg = 'the tangent stiffness is not ' &
                  // 'positive definite (buckling, or a mechanism: check &boundary): pivot of ' &
                  // trim(describe_equation(model%msh, bad_eq))
               if (stat /= 0) then
                  errmsg = 'static: increment ' // int_str(inc) // ' (load factor ' // real_str(lam) &
                     // '): ' // trim(errmsg)
                  return
               end if
               call global_solve(kt, r, stat, errmsg)
               if (stat /= 0) return
               d = d + r
               num = sum(r**2)
               den = sum((d - d_start)**2)                 ! the measure of eq. (18)
               if (num <= model%cr2*den .or. num == 0.0_dp) exit newton_iterations
            end do newton_iterations
            if (it > model%max_nonlinear_iter) then       ! not converged
               stat = 1
               write (errmsg, '(a,i0,a,f8.5,a,i0,a)') &
                  'static: Newton did not converge in increment ', inc, ' (load factor ', lam, ') in ', &
                  model%max_nonlinear_iter, ' iterations (&analysis max_nonlinear_iter): ' // &
                  'give more &load increments'
               return
            end if
         end if
         call internal_force(model, d, fint)
         res%load_factor(inc) = lam
         res%w_centre(inc) = centre_deflection(model, d)
         res%iterations(inc) = it
         res%residual(inc) = norm2(lam*f - fint)/max(norm2(lam*f), tiny(1.0_dp))
         res%increments = inc
         res%d = d
      end do load_increments
      call global_release(kt)
   end subroutine static_solve

   !> The internal force f_int(D) = K_L D + K_N(D) D (eq. 15; K_N = 0 in the linear theory).
   subroutine internal_force(model, d, fint)
      type(model_t), intent(in) :: model     !< model
      real(dp), intent(in) :: d(:)           !< displacements (m, rad)
      real(dp), intent(out) :: fint(:)       !< internal force (N)
      real(dp) :: fn(size(d))
      call global_matvec(model%stiff, d, fint)
      call nonlinear_force(model, d, fn)
      fint = fint + fn
   end subroutine internal_force

end module static_analysis
