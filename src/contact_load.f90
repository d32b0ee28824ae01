!> How the contact force enters the plate: the load of eq. (10), and the
!> plate deflection under the impactor of eq. (13) that goes with it.
!>
!>  - 'point' (the paper's eq. 10, F delta w_p): the force at the impact
!>    node, and the deflection of that node. The Mindlin plate has no finite
!>    deflection under a point force (it grows like ln(1/r) at the load),
!>    so this load has no mesh-converged answer: the deflection under the
!>    impactor grows as the elements there shrink (docs/VALIDATION.md).
!>  - 'hertz' (the default): the force spread over the contact area, a disc
!>    of radius a = sqrt(R alpha) (R the nose radius, alpha the indentation)
!>    with Hertz's pressure
!>        p(r) = 3 F / (2 pi a^2) sqrt(1 - r^2/a^2),
!>    integrated into the consistent load vector f_i = int phi_i p dA over
!>    the elements the disc covers (on the w freedoms); the deflection under
!>    the impactor is the pressure-weighted mean w_p = (1/F) int p w dA,
!>    the work-conjugate of that load. When the disc is small against the
!>    element this is the point force; when the mesh resolves it the answer
!>    converges.
!>
!> The contact radius belongs to a force: a = sqrt(R alpha(F)), alpha(F) the
!> law's indentation at F after the committed history (law_indentation in
!> module contact_law, the inverse of eq. 11-12), so that the load is a
!> fixed function of the force in the contact iterations; at convergence
!> F = F_law(alpha) and a = sqrt(R alpha). It is kept at most R.
!>
!> A load pattern is the load vector of a unit contact force on the whole
!> plate, over the few equations it touches: F c_j on equation eq(j). On a
!> quarter or half model it carries the model's share, sum c_j = 1/sym_factor
!> (less what falls on held freedoms, which the supports take).
!>
!> The quadrature of the disc: n_radial Gauss-Legendre points in t, with
!> r = a sin t (which turns sqrt(1 - s^2) s ds into cos^2 t sin t dt, a smooth
!> integrand), times n_angular equally spaced angles offset by half a
!> spacing, so that no point lies on a symmetry line and each quadrant holds
!> exactly a quarter of the points (n_angular is a multiple of 4). The
!> weights are scaled so that the points the model keeps carry its share
!> exactly.
module contact_load
   use kinds, only: dp, pi
   use mesh, only: mesh_t, locate_point
   use shape_functions, only: nen, shape9
   use gauss_rules, only: gauss_legendre
   implicit none
   private
   public :: contact_load_t, load_pattern_t, contact_load_init, load_pattern, pattern_mean, &
             pattern_add, pattern_load, load_point, load_hertz, load_kind_names

   !> Kinds of load, by code, and their names in the deck (&contact load).
   integer, parameter :: load_point = 1, load_hertz = 2
   character(len=5), parameter :: load_kind_names(2) = [character(len=5) :: 'point', 'hertz']
   !> Points of the disc quadrature (module header): radial, angular.
   integer, parameter :: n_radial = 8, n_angular = 48

   !> The contact load of a run.
   type :: contact_load_t
      integer :: kind = load_hertz            !< load_point or load_hertz
      real(dp) :: nose_radius = 0.0_dp        !< R (m)
      real(dp) :: centre(2) = 0.0_dp          !< impact point (m), from the plate centre
      logical :: sym(2) = .false.             !< x = centre(1), y = centre(2) is a symmetry line
      integer :: eq_point = 0                 !< equation of w at the impact point
      real(dp) :: share = 1.0_dp              !< share of the force the model carries (1/sym_factor)
      real(dp), allocatable :: s(:)           !< disc points: r/a
      real(dp), allocatable :: dir(:,:)       !< (2, npoint) disc points: (cos, sin) of the angle
      real(dp), allocatable :: wt(:)          !< disc points: fraction of the force, summing to 1
   end type contact_load_t

   !> The load vector of a unit contact force, on the equations it touches.
   type :: load_pattern_t
      real(dp) :: radius = 0.0_dp             !< contact radius a (m); 0 for the point force
      integer :: n = 0                        !< equations touched
      integer, allocatable :: eq(:)           !< their numbers
      real(dp), allocatable :: c(:)           !< load on each per newton of contact force (-)
      real(dp) :: total = 1.0_dp              !< the model's share of the force, held freedoms included
   end type load_pattern_t

contains

   !> The contact load of the mesh m: kind, nose radius R (m), and the
   !> disc quadrature.
   subroutine contact_load_init(m, kind, nose_radius, cl, stat)
      type(mesh_t), intent(in) :: m                !< mesh with equation numbers
      integer, intent(in) :: kind                  !< load_point or load_hertz
      real(dp), intent(in) :: nose_radius          !< R (m)
      type(contact_load_t), intent(out) :: cl      !< the contact load
      integer, intent(out) :: stat                 !< 0, or LAPACK's info of the Gauss rule
      real(dp) :: t(n_radial), wr(n_radial), theta
      integer :: i, j, k

      cl%kind = kind
      cl%nose_radius = nose_radius
      cl%centre = [m%x_impact, m%y_impact]
      cl%sym = [m%sym_x, m%sym_y]
      cl%eq_point = m%eq(3, m%impact_node)
      cl%share = 1.0_dp/m%sym_factor
      call gauss_legendre(n_radial, t, wr, stat)
      if (stat /= 0) return
      ! t in [0, pi/2]: r/a = sin t, fraction of F = (3/(2 pi)) cos^2 t sin t dt dtheta
      t = 0.25_dp*pi*(t + 1.0_dp);  wr = 0.25_dp*pi*wr
      allocate (cl%s(n_radial*n_angular), cl%dir(2, n_radial*n_angular), cl%wt(n_radial*n_angular))
      k = 0
      angles: do j = 1, n_angular
         theta = 2.0_dp*pi*(real(j, dp) - 0.5_dp)/real(n_angular, dp)
         radii: do i = 1, n_radial
            k = k + 1
            cl%s(k) = sin(t(i))
            cl%dir(:, k) = [cos(theta), sin(theta)]
            cl%wt(k) = 3.0_dp*cos(t(i))**2*sin(t(i))*wr(i)/real(n_angular, dp)
         end do radii
      end do angles
      cl%wt = cl%wt/sum(cl%wt)
   end subroutine contact_load_init

   !> The load pattern of the contact radius a (m) on the mesh m (module
   !> header); the point force when the load is 'point' or a = 0.
   pure subroutine load_pattern(cl, m, a, pat)
      type(contact_load_t), intent(in) :: cl       !< the contact load
      type(mesh_t), intent(in) :: m                !< mesh with equation numbers
      real(dp), intent(in) :: a                    !< contact radius (m)
      type(load_pattern_t), intent(inout) :: pat   !< the pattern (arrays reused)
      real(dp) :: p(2), xi(2), phi(nen), kept
      integer :: k, e, i, eq, j

      pat%total = cl%share
      pat%radius = 0.0_dp
      if (cl%kind == load_point .or. .not. (a > 0.0_dp)) then
         call make_room(pat, 1)
         pat%n = 1;  pat%eq(1) = cl%eq_point;  pat%c(1) = cl%share
         return
      end if
      pat%radius = min(a, cl%nose_radius)
      call make_room(pat, 1)
      pat%n = 0
      kept = 0.0_dp
      disc_points: do k = 1, size(cl%wt)
         if ((cl%sym(1) .and. cl%dir(1, k) < 0.0_dp) .or. (cl%sym(2) .and. cl%dir(2, k) < 0.0_dp)) cycle
         p = cl%centre + pat%radius*cl%s(k)*cl%dir(:, k)
         call locate_point(m, p, e, xi)
         if (e == 0) cycle disc_points          ! off the plate: the rest carries the force
         kept = kept + cl%wt(k)
         phi = shape9(xi(1), xi(2))
         nodes: do i = 1, nen
            eq = m%eq(3, m%conn(i, e))
            if (eq == 0) cycle nodes             ! a support takes it
            j = findloc(pat%eq(:pat%n), eq, dim=1)
            if (j == 0) then
               call make_room(pat, pat%n + 1)
               pat%n = pat%n + 1;  j = pat%n
               pat%eq(j) = eq;  pat%c(j) = 0.0_dp
            end if
            pat%c(j) = pat%c(j) + cl%wt(k)*phi(i)
         end do nodes
      end do disc_points
      if (kept > 0.0_dp) pat%c(:pat%n) = pat%c(:pat%n)*cl%share/kept
   end subroutine load_pattern

   !> Grows the pattern's arrays to hold at least n entries, keeping them.
   pure subroutine make_room(pat, n)
      type(load_pattern_t), intent(inout) :: pat   !< the pattern
      integer, intent(in) :: n                     !< entries needed
      integer, allocatable :: eq_new(:)
      real(dp), allocatable :: c_new(:)
      if (allocated(pat%eq)) then
         if (size(pat%eq) >= n) return
         allocate (eq_new(2*n), c_new(2*n))
         eq_new(:size(pat%eq)) = pat%eq;  c_new(:size(pat%c)) = pat%c
         call move_alloc(eq_new, pat%eq);  call move_alloc(c_new, pat%c)
      else
         allocate (pat%eq(max(n, 16)), pat%c(max(n, 16)))
      end if
   end subroutine make_room

   !> The plate deflection under the impactor, eq. (13): the pressure-
   !> weighted mean of w over the contact area (the node's w for the point
   !> force), w_p = sum c_j d(eq_j) / total (m).
   pure function pattern_mean(pat, d) result(w)
      type(load_pattern_t), intent(in) :: pat      !< the pattern
      real(dp), intent(in) :: d(:)                 !< global displacements
      real(dp) :: w
      w = dot_product(pat%c(:pat%n), d(pat%eq(:pat%n)))/pat%total
   end function pattern_mean

   !> rhs = rhs + f (pattern): the contact force f (N) on the model.
   pure subroutine pattern_add(pat, f, rhs)
      type(load_pattern_t), intent(in) :: pat      !< the pattern
      real(dp), intent(in) :: f                    !< contact force on the whole plate (N)
      real(dp), intent(inout) :: rhs(:)            !< global load vector
      rhs(pat%eq(:pat%n)) = rhs(pat%eq(:pat%n)) + f*pat%c(:pat%n)
   end subroutine pattern_add

   !> The load vector f (pattern) of the contact force f (N) on the model,
   !> as a whole vector of n equations.
   pure function pattern_load(pat, f, n) result(v)
      type(load_pattern_t), intent(in) :: pat      !< the pattern
      real(dp), intent(in) :: f                    !< contact force on the whole plate (N)
      integer, intent(in) :: n                     !< equations
      real(dp) :: v(n)
      v = 0.0_dp
      call pattern_add(pat, f, v)
   end function pattern_load

end module contact_load
