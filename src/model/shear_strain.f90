!> The transverse shear strains of the 9-node element, gamma = (eps4, eps5)
!> = (psi_y + w,y, psi_x + w,x) (eq. 2), as the element evaluates them:
!> the discrete shear operator and the points that integrate its energy.
!> The rules against shear locking ('selective', the paper's section 2.3;
!> 'full'; 'stabilized'; 'mitc9', the default): above the rule codes;
!> MITC9's assumed covariant field: above add_mitc9_point.
!>
!> The operator: at shear point g, gamma(:) = sum over the nodes i of
!>     b(:, 1, i, g) w_i + b(:, 2, i, g) psi_x_i + b(:, 3, i, g) psi_y_i,
!> rows (eps4, eps5); the shear energy is 1/2 sum_g wj(g) gamma^T Abar gamma.
!> More: docs/VALIDATION.md, "The element".
module shear_strain
   use kinds, only: dp
   use shape_functions, only: nen, shape9, shape9_derivs
   use gauss_rules, only: gauss_2d
   implicit none
   private
   public :: shear_rule_t, shear_operator_t, shear_operator, shear_rule_names, &
             shear_selective, shear_stabilized, shear_full, shear_mitc9, shear_rule_code

   !> With the plain displacement interpolation the 9-node element locks in
   !> shear when the plate is thin; each rule below is a way out, and they
   !> differ in what they leave behind (docs/VALIDATION.md, "The element"):
   !>
   !>  - 'selective'  (the paper's rule, section 2.3): the shear energy at 2x2
   !>    Gauss points. It does not lock, but leaves one zero-energy mode per
   !>    element (a zig-zag of w with zero slope at the 2x2 points) and near
   !>    mechanisms in assembled meshes, which a point force excites: the
   !>    answer drifts as the mesh is refined.
   !>  - 'full':      3x3 points, the plain element: no spurious mode, locks
   !>    when the plate is thin.
   !>  - 'stabilized': (1 - eps) 'selective' + eps 'full' (eps = &mesh
   !>    stabilization): gives the mode a little stiffness.
   !>  - 'mitc9':     an assumed covariant shear strain field, tied to the
   !>    displacements at tying points (add_mitc9_point; MITC9: Bucalem & Bathe, Int. J.
   !>    Numer. Meth. Engng 36, 1993; the same tying as Huang & Hinton's
   !>    assumed-strain 9-node element, Eng. Comput. 1, 1984), integrated at
   !>    3x3 points. Neither locks nor leaves a mechanism: one element has
   !>    exactly the rigid-body zero eigenvalues, and it passes the patch
   !>    test. The default ('auto').
   !>
   !> The rules, by code.
   integer, parameter :: shear_selective = 1, shear_stabilized = 2, shear_full = 3, shear_mitc9 = 4
   !> Their names in the deck (&mesh shear_rule), in the order of the codes.
   character(len=10), parameter :: shear_rule_names(4) = &
      [character(len=10) :: 'selective', 'stabilized', 'full', 'mitc9']
   !> Most shear points of a rule: 'stabilized' has 2x2 + 3x3.
   integer, parameter :: max_shear_points = 13

   !> A transverse shear rule.
   type :: shear_rule_t
      integer :: code = shear_mitc9        !< shear_selective, ..., shear_mitc9
      real(dp) :: eps = 0.0_dp             !< fraction of 3x3 shear of 'stabilized' (-)
   end type shear_rule_t

   !> The discrete shear strain operator of one element (as above).
   type :: shear_operator_t
      integer :: npoint = 0                                !< shear points used
      real(dp) :: b(2, 3, nen, max_shear_points) = 0.0_dp  !< (eps4|eps5, w|psi_x|psi_y, node, point) (1/m or -)
      real(dp) :: wj(max_shear_points) = 0.0_dp            !< weight * det J (* share) (m^2)
   end type shear_operator_t

   real(dp), parameter :: r_tie = 0.577350269189625764509148780501957_dp   ! 1/sqrt(3)
   real(dp), parameter :: s_tie = 0.774596669241483377035853079956480_dp   ! sqrt(3/5)

contains

   !> The code of a rule's deck name; 0 when the name is not a rule.
   pure function shear_rule_code(name) result(code)
      character(len=*), intent(in) :: name   !< 'selective', 'stabilized', 'full' or 'mitc9'
      integer :: code
      integer :: k
      code = 0
      do k = 1, size(shear_rule_names)
         if (trim(name) == trim(shear_rule_names(k))) code = k
      end do
   end function shear_rule_code

   !> The shear operator of the element with node coordinates xe under rule.
   !> ok is false when det J is not positive at a point used.
   pure subroutine shear_operator(xe, rule, op, ok)
      real(dp), intent(in) :: xe(2, nen)           !< node coordinates (m)
      type(shear_rule_t), intent(in) :: rule       !< the rule
      type(shear_operator_t), intent(out) :: op    !< its operator
      logical, intent(out) :: ok                   !< det J > 0 at every point used
      real(dp) :: p2(2, 4), w2(4), p3(2, 9), w3(9)
      integer :: g

      call gauss_2d(2, p2, w2)
      call gauss_2d(3, p3, w3)
      ok = .true.
      select case (rule%code)
      case (shear_selective)
         do g = 1, 4
            call add_displacement_point(xe, p2(:, g), w2(g), op, ok)
         end do
      case (shear_full)
         do g = 1, 9
            call add_displacement_point(xe, p3(:, g), w3(g), op, ok)
         end do
      case (shear_stabilized)
         do g = 1, 4
            call add_displacement_point(xe, p2(:, g), (1.0_dp - rule%eps)*w2(g), op, ok)
         end do
         do g = 1, 9
            call add_displacement_point(xe, p3(:, g), rule%eps*w3(g), op, ok)
         end do
      case default   ! shear_mitc9
         do g = 1, 9
            call add_mitc9_point(xe, p3(:, g), w3(g), op, ok)
         end do
      end select
   end subroutine shear_operator

   !> Adds to op the point pt (reference coordinates, weight w) with gamma
   !> from the displacement interpolation; ok false when det J <= 0 there.
   pure subroutine add_displacement_point(xe, pt, w, op, ok)
      real(dp), intent(in) :: xe(2, nen), pt(2), w
      type(shear_operator_t), intent(inout) :: op
      logical, intent(inout) :: ok
      real(dp) :: phi(nen), dref(2, nen), jac(2, 2), det, dxy(2, nen)
      phi = shape9(pt(1), pt(2))
      dref = shape9_derivs(pt(1), pt(2))
      jac = matmul(dref, transpose(xe))
      det = jac(1,1)*jac(2,2) - jac(1,2)*jac(2,1)
      if (.not. (det > 0.0_dp)) then
         ok = .false.
         return
      end if
      dxy = matmul(reshape([jac(2,2), -jac(2,1), -jac(1,2), jac(1,1)], [2, 2])/det, dref)
      op%npoint = op%npoint + 1
      associate (b => op%b(:, :, :, op%npoint))
         b(1, 1, :) = dxy(2, :);  b(1, 2, :) = 0.0_dp;  b(1, 3, :) = phi   ! eps4 = psi_y + w,y
         b(2, 1, :) = dxy(1, :);  b(2, 2, :) = phi;     b(2, 3, :) = 0.0_dp   ! eps5 = psi_x + w,x
      end associate
      op%wj(op%npoint) = w*det
   end subroutine add_displacement_point

   !> MITC9. With g_xi = (x,xi, y,xi) and g_eta the covariant base vectors of
   !> the isoparametric map (J(i,:) = g_i), the covariant shear strains are
   !>     e_xi  = gamma . g_xi  = w,xi  + psi_x x,xi  + psi_y y,xi
   !>     e_eta = gamma . g_eta = w,eta + psi_x x,eta + psi_y y,eta
   !> (no inverse Jacobian: they are exact at any point of the element). The
   !> assumed field takes e_xi linear in xi and quadratic in eta, e_eta the
   !> other way round, interpolated from their values at the tying points
   !>     e_xi:   xi = -r, +r  x  eta = -s, 0, +s
   !>     e_eta:  xi = -s, 0, +s  x  eta = -r, +r,    r = 1/sqrt(3), s = sqrt(3/5)
   !> with the Lagrange polynomials through those points, and at an
   !> integration point (gamma_x, gamma_y) = J^-1 (e_xi, e_eta).
   !>
   !> Adds to op the point pt (reference coordinates, weight w) with gamma
   !> of the MITC9 assumed field (as above); ok false when det J <= 0.
   pure subroutine add_mitc9_point(xe, pt, w, op, ok)
      real(dp), intent(in) :: xe(2, nen), pt(2), w
      type(shear_operator_t), intent(inout) :: op
      logical, intent(inout) :: ok
      real(dp) :: e_xi(3, nen), e_eta(3, nen), cov(3, nen, 2), jac(2, 2), jinv(2, 2), det
      real(dp) :: lr(2), ls(3)
      integer :: i, j, k
      ! e_xi: linear in xi through -r, +r; quadratic in eta through -s, 0, +s
      lr = lagrange_2(pt(1));  ls = lagrange_3(pt(2))
      e_xi = 0.0_dp
      do j = 1, 3
         do i = 1, 2
            cov = covariant_rows(xe, [(2*i - 3)*r_tie, (j - 2)*s_tie])
            e_xi = e_xi + lr(i)*ls(j)*cov(:, :, 1)
         end do
      end do
      ! e_eta: quadratic in xi through -s, 0, +s; linear in eta through -r, +r
      ls = lagrange_3(pt(1));  lr = lagrange_2(pt(2))
      e_eta = 0.0_dp
      do j = 1, 2
         do i = 1, 3
            cov = covariant_rows(xe, [(i - 2)*s_tie, (2*j - 3)*r_tie])
            e_eta = e_eta + ls(i)*lr(j)*cov(:, :, 2)
         end do
      end do
      jac = matmul(shape9_derivs(pt(1), pt(2)), transpose(xe))
      det = jac(1,1)*jac(2,2) - jac(1,2)*jac(2,1)
      if (.not. (det > 0.0_dp)) then
         ok = .false.
         return
      end if
      jinv = reshape([jac(2,2), -jac(2,1), -jac(1,2), jac(1,1)], [2, 2])/det
      op%npoint = op%npoint + 1
      ! (gamma_x, gamma_y) = J^-1 (e_xi, e_eta); rows eps4 = gamma_y, eps5 = gamma_x
      do k = 1, 3
         op%b(2, k, :, op%npoint) = jinv(1, 1)*e_xi(k, :) + jinv(1, 2)*e_eta(k, :)
         op%b(1, k, :, op%npoint) = jinv(2, 1)*e_xi(k, :) + jinv(2, 2)*e_eta(k, :)
      end do
      op%wj(op%npoint) = w*det
   end subroutine add_mitc9_point

   !> The covariant shear strains e_xi (:, :, 1) and e_eta (:, :, 2) at the
   !> reference point pt, as rows over (w, psi_x, psi_y) of each node.
   pure function covariant_rows(xe, pt) result(cov)
      real(dp), intent(in) :: xe(2, nen), pt(2)
      real(dp) :: cov(3, nen, 2)
      real(dp) :: phi(nen), dref(2, nen), jac(2, 2)
      integer :: d
      phi = shape9(pt(1), pt(2))
      dref = shape9_derivs(pt(1), pt(2))
      jac = matmul(dref, transpose(xe))      ! jac(d, :) = g_d = (x,d, y,d)
      do d = 1, 2
         cov(1, :, d) = dref(d, :)           ! w,d
         cov(2, :, d) = jac(d, 1)*phi        ! psi_x x,d
         cov(3, :, d) = jac(d, 2)*phi        ! psi_y y,d
      end do
   end function covariant_rows

   !> Linear Lagrange polynomials through -r, +r at t.
   pure function lagrange_2(t) result(l)
      real(dp), intent(in) :: t
      real(dp) :: l(2)
      l = [0.5_dp*(1.0_dp - t/r_tie), 0.5_dp*(1.0_dp + t/r_tie)]
   end function lagrange_2

   !> Quadratic Lagrange polynomials through -s, 0, +s at t.
   pure function lagrange_3(t) result(l)
      real(dp), intent(in) :: t
      real(dp) :: l(3)
      l = [0.5_dp*t*(t - s_tie), s_tie**2 - t*t, 0.5_dp*t*(t + s_tie)]/s_tie**2
   end function lagrange_3

end module shear_strain
