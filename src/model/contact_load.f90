!> How the contact force enters the plate: the load of eq. (10), and the
!> plate deflection under the impactor of eq. (13) that goes with it.
!>  - 'point' (the paper's eq. 10, F delta w_p): the force at the impact
!>    node and that node's deflection; under a point force the Mindlin
!>    plate's deflection has no mesh-converged answer (docs/VALIDATION.md).
!>  - 'hertz' (the default): the force spread over the contact disc of
!>    radius a = sqrt(R alpha) with Hertz's pressure
!>        p(r) = 3 F / (2 pi a^2) sqrt(1 - r^2/a^2),
!>    as the consistent load f_i = int phi_i p dA on the w freedoms, and the
!>    work-conjugate deflection w_p = (1/F) int p w dA.
!> The radius belongs to a force: a = sqrt(R alpha(F)), alpha(F) the law's
!> indentation after the committed history (law_indentation), at most R.
!> The load pattern, its polynomials in a and the disc's quadrature: above
!> load_pattern. More: docs/MODEL.md.
module contact_load
   use kinds, only: dp, pi
   use mesh, only: mesh_t, locate_point
   use shape_functions, only: nen, node_position
   use gauss_rules, only: gauss_legendre
   implicit none
   private
   public :: contact_load_t, load_pattern_t, contact_load_init, load_pattern, pattern_mean, &
             pattern_add, pattern_load, load_point, load_hertz

   !> Kinds of load, by code (&contact load = 'point', 'hertz').
   integer, parameter :: load_point = 1, load_hertz = 2
   !> Points of the disc quadrature (above load_pattern): radial, angular.
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
      !> c_j(a) = sum_p poly(p, j) a^p while valid(1) <= a <= valid(2) (above load_pattern)
      real(dp), allocatable :: poly(:,:)      !< (0:4, equations) the polynomials
      real(dp) :: valid(2) = [1.0_dp, -1.0_dp]   !< their interval of a (m); empty: none
      real(dp) :: built_for(6) = 0.0_dp       !< the contact load and mesh they belong to (load_key)
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

   !> A load pattern is the load vector of a unit contact force on the whole
   !> plate, over the few equations it touches: F c_j on equation eq(j). On a
   !> quarter or half model it carries the model's share, sum c_j = 1/sym_factor
   !> (less what falls on held freedoms, which the supports take).
   !>
   !> The pattern as a function of a: on the structured mesh (elements between
   !> straight grid lines) the reference coordinates of a disc point r = a s
   !> (cos t, sin t) are affine in a as long as the point stays in its
   !> element, so each coefficient c_j(a) is a polynomial of degree 4 in a
   !> (a product of two quadratic Lagrange polynomials, summed over the
   !> points). load_pattern keeps these polynomials in the pattern with the
   !> interval of a in which no point changes element, and evaluates them
   !> while a stays in it; it builds them again (one pass over the disc points)
   !> only when a leaves it. The contact iterations call it for many close
   !> radii in every step.
   !>
   !> The quadrature of the disc: n_radial Gauss-Legendre points in t, with
   !> r = a sin t (which turns sqrt(1 - s^2) s ds into cos^2 t sin t dt, a smooth
   !> integrand), times n_angular equally spaced angles offset by half a
   !> spacing, so that no point lies on a symmetry line and each quadrant holds
   !> exactly a quarter of the points (n_angular is a multiple of 4). The
   !> weights are scaled so that the points the model keeps carry its share
   !>
   !> The load pattern of the contact radius a (m) on the mesh m (module
   !> header); the point force when the load is 'point' or a = 0.
   pure subroutine load_pattern(cl, m, a, pat)
      type(contact_load_t), intent(in) :: cl       !< the contact load
      type(mesh_t), intent(in) :: m                !< mesh with equation numbers
      real(dp), intent(in) :: a                    !< contact radius (m)
      type(load_pattern_t), intent(inout) :: pat   !< the pattern (arrays and polynomials reused)
      real(dp) :: r
      integer :: j

      pat%total = cl%share
      pat%radius = 0.0_dp
      if (cl%kind == load_point .or. .not. (a > 0.0_dp)) then
         call make_room(pat, 1)
         pat%n = 1;  pat%eq(1) = cl%eq_point;  pat%c(1) = cl%share
         pat%valid = [1.0_dp, -1.0_dp]
         return
      end if
      r = min(a, cl%nose_radius)
      if (.not. (pat%valid(1) <= r .and. r <= pat%valid(2) .and. pattern_built_for(pat, cl, m))) &
         call pattern_polynomials(cl, m, r, pat)
      pat%radius = r
      do j = 1, pat%n
         pat%c(j) = pat%poly(0, j) + r*(pat%poly(1, j) + r*(pat%poly(2, j) + r*(pat%poly(3, j) &
                    + r*pat%poly(4, j))))
      end do
   end subroutine load_pattern

   !> The polynomials c_j(a) of the pattern about the radius r and the
   !> interval of a in which they hold (above load_pattern): each disc point in
   !> the element that holds it at r, its shape functions along the ray as
   !> products of quadratics in a.
   pure subroutine pattern_polynomials(cl, m, r, pat)
      type(contact_load_t), intent(in) :: cl       !< the contact load
      type(mesh_t), intent(in) :: m                !< mesh with equation numbers
      real(dp), intent(in) :: r                    !< contact radius (m), > 0
      type(load_pattern_t), intent(inout) :: pat   !< the pattern: its polynomials and interval
      real(dp) :: p(2), xi(2), lo(2), hi(2), slope(2), base(2), lq(0:2, 3, 2), kept, reach, term(0:4)
      integer :: k, e, i, eq, j, d, ie, je

      call make_room(pat, 1)
      pat%n = 0
      pat%valid = [0.0_dp, cl%nose_radius]
      pat%built_for = load_key(cl, m)
      kept = 0.0_dp
      disc_points: do k = 1, size(cl%wt)
         if ((cl%sym(1) .and. cl%dir(1, k) < 0.0_dp) .or. (cl%sym(2) .and. cl%dir(2, k) < 0.0_dp)) cycle
         p = cl%centre + r*cl%s(k)*cl%dir(:, k)
         call locate_point(m, p, e, xi)
         if (e == 0) then                       ! off the plate: the rest carries the force
            pat%valid(1) = max(pat%valid(1), r) ! (and it stays off as a grows)
            cycle disc_points
         end if
         kept = kept + cl%wt(k)
         ! -- xi(a) = base + slope a along the ray, while the point stays in e
         ie = mod(e - 1, m%nx);  je = (e - 1)/m%nx
         lo = [m%xline(ie), m%yline(je)];  hi = [m%xline(ie + 1), m%yline(je + 1)]
         slope = 2.0_dp*cl%s(k)*cl%dir(:, k)/(hi - lo)
         base = xi - r*slope
         do d = 1, 2
            if (slope(d) /= 0.0_dp) then       ! xi stays within [-1, 1]
               reach = (sign(1.0_dp, slope(d)) - base(d))/slope(d)
               pat%valid(2) = min(pat%valid(2), reach)
               reach = (-sign(1.0_dp, slope(d)) - base(d))/slope(d)
               pat%valid(1) = max(pat%valid(1), reach)
            end if
            ! the quadratic Lagrange polynomials of xi(a) (module shape_functions), coefficients of a^0..a^2
            lq(:, 1, d) = 0.5_dp*[base(d)**2 - base(d), 2.0_dp*base(d)*slope(d) - slope(d), slope(d)**2]
            lq(:, 2, d) = [1.0_dp - base(d)**2, -2.0_dp*base(d)*slope(d), -slope(d)**2]
            lq(:, 3, d) = 0.5_dp*[base(d)**2 + base(d), 2.0_dp*base(d)*slope(d) + slope(d), slope(d)**2]
         end do
         nodes: do i = 1, nen
            eq = m%eq(3, m%conn(i, e))
            if (eq == 0) cycle nodes             ! a support takes it
            j = findloc(pat%eq(:pat%n), eq, dim=1)
            if (j == 0) then
               call make_room(pat, pat%n + 1)
               pat%n = pat%n + 1;  j = pat%n
               pat%eq(j) = eq;  pat%poly(:, j) = 0.0_dp
            end if
            term = product_of_quadratics(lq(:, node_position(1, i), 1), lq(:, node_position(2, i), 2))
            pat%poly(:, j) = pat%poly(:, j) + cl%wt(k)*term
         end do nodes
      end do disc_points
      if (kept > 0.0_dp) pat%poly(:, :pat%n) = pat%poly(:, :pat%n)*cl%share/kept
      if (pat%n == 0) pat%valid = [1.0_dp, -1.0_dp]
      ! a point exactly on an element side may be held by either element: keep r itself valid
      pat%valid = [min(pat%valid(1), r), max(pat%valid(2), r)]
   end subroutine pattern_polynomials

   !> What a pattern's polynomials belong to: the contact load (its share,
   !> centre and nose radius) and the mesh (its equations and grid lines).
   pure function load_key(cl, m) result(key)
      type(contact_load_t), intent(in) :: cl       !< the contact load
      type(mesh_t), intent(in) :: m                !< the mesh
      real(dp) :: key(6)
      key = [cl%share, cl%centre(1), cl%centre(2), cl%nose_radius, real(m%neq, dp), sum(m%xline) + pi*sum(m%yline)]
   end function load_key

   !> Whether the pattern's polynomials were built for the contact load cl
   !> and the mesh m: their key is load_key's, bit for bit (a cache key, not
   !> a quantity; a pattern never built has the key 0, which no contact
   !> load has: its share is positive).
   pure logical function pattern_built_for(pat, cl, m)
      type(load_pattern_t), intent(in) :: pat      !< the pattern
      type(contact_load_t), intent(in) :: cl       !< the contact load
      type(mesh_t), intent(in) :: m                !< the mesh
      pattern_built_for = all(pat%built_for == load_key(cl, m))
   end function pattern_built_for

   !> Coefficients of a^0..a^4 of the product of two quadratics in a.
   pure function product_of_quadratics(u, v) result(w)
      real(dp), intent(in) :: u(0:2), v(0:2)   !< coefficients of a^0..a^2
      real(dp) :: w(0:4)
      w = [u(0)*v(0), u(0)*v(1) + u(1)*v(0), u(0)*v(2) + u(1)*v(1) + u(2)*v(0), u(1)*v(2) + u(2)*v(1), &
           u(2)*v(2)]
   end function product_of_quadratics

   !> Grows the pattern's arrays (equations, loads, polynomials) to hold at
   !> least n entries, keeping them.
   pure subroutine make_room(pat, n)
      type(load_pattern_t), intent(inout) :: pat   !< the pattern
      integer, intent(in) :: n                     !< entries needed
      integer, allocatable :: eq_new(:)
      real(dp), allocatable :: c_new(:), poly_new(:,:)
      if (allocated(pat%eq) .and. allocated(pat%poly)) then
         if (size(pat%eq) >= n) return
         allocate (eq_new(2*n), c_new(2*n), poly_new(0:4, 2*n))
         eq_new(:size(pat%eq)) = pat%eq;  c_new(:size(pat%c)) = pat%c;  poly_new(:, :size(pat%poly, 2)) = pat%poly
         call move_alloc(eq_new, pat%eq);  call move_alloc(c_new, pat%c);  call move_alloc(poly_new, pat%poly)
      else
         if (allocated(pat%eq)) deallocate (pat%eq)
         if (allocated(pat%c)) deallocate (pat%c)
         if (allocated(pat%poly)) deallocate (pat%poly)
         allocate (pat%eq(max(n, 16)), pat%c(max(n, 16)))
         allocate (pat%poly(0:4, max(n, 16)), source=0.0_dp)   ! defined: a restart point holds it
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
