!> Closed-form and series solutions the code is validated against
!> (docs/VALIDATION.md). Each is written out here, with its source, so that
!> the validation does not rest on numbers copied from elsewhere.
!>
!> 1. Navier solution, first-order shear deformation theory (FSDT), simply
!>    supported specially orthotropic plate (symmetric cross-ply or
!>    isotropic: B = 0, A16 = A26 = D16 = D26 = 0, Abar45 = 0).
!>    J. N. Reddy, Mechanics of Laminated Composite Plates and Shells,
!>    2nd ed., CRC Press 2004, section 7.3 (Navier solutions of cross-ply
!>    plates, FSDT). Plate 0 <= x <= a, 0 <= y <= b, the "hard" simple
!>    support w = psi_s = 0 of src/model/mesh.f90. With alpha = m pi/a,
!>    beta = n pi/b and
!>        w     = sum W_mn sin(alpha x) sin(beta y)
!>        psi_x = sum X_mn cos(alpha x) sin(beta y)
!>        psi_y = sum Y_mn sin(alpha x) cos(beta y)
!>    each (m, n) obeys   [S]{W X Y} + [M]{W X Y}'' = {Q_mn 0 0}   with
!>        S11 = A55 alpha^2 + A44 beta^2,  S12 = A55 alpha,  S13 = A44 beta,
!>        S22 = D11 alpha^2 + D66 beta^2 + A55,  S23 = (D12 + D66) alpha beta,
!>        S33 = D66 alpha^2 + D22 beta^2 + A44,
!>        M = diag(I0, I2, I2)   (I0 = P, I2 = I of eq. 9),
!>    A44, A55 the shear stiffnesses with the correction factors included
!>    (Abar of eq. 6). Loads: uniform q0: Q_mn = 16 q0/(pi^2 m n), m, n odd;
!>    sinusoidal q0 sin(pi x/a) sin(pi y/b): Q_11 = q0 only; a force P at
!>    the centre: Q_mn = 4 P/(a b) sin(m pi/2) sin(n pi/2) (its FSDT series
!>    diverges like log at the load point: shear; the CLPT series converges).
!>    With S phi_k = omega_k^2 M phi_k (k = 1..3, phi_k^T M phi_k = 1), the
!>    centre deflection under a load applied at t = 0 and held is
!>        w_c(t) = sum_mn sum_k c_mnk (1 - cos omega_mnk t),
!>        c_mnk  = s_mn phi_k(1)^2 Q_mn / omega_k^2,  s_mn = sin(m pi/2) sin(n pi/2),
!>    The static centre deflection is sum_mn s_mn W_mn with S {W X Y} =
!>    {Q_mn 0 0} solved directly (LAPACK dposv); it equals sum c_mnk
!>    (S^-1 = sum phi_k phi_k^T/omega_k^2), but the modal sum loses about
!>    eps (omega_3/omega_1)^2 ~ eps (a/h)^4 of relative accuracy, which
!>    matters beyond a/h ~ 1000, while the direct solve loses eps (a/h)^2.
!>    The natural frequencies are the omega_mnk. navier_fsdt builds the
!>    table of terms.
!>
!> 2. Navier solution, classical (Kirchhoff) plate theory, same plate:
!>    W_mn = Q_mn / (pi^4 [D11 (m/a)^4 + 2 (D12 + 2 D66)(m/a)^2 (n/b)^2 + D22 (n/b)^4]),
!>    Reddy (2004) section 5.2; Timoshenko & Woinowsky-Krieger, Theory of
!>    Plates and Shells, 2nd ed. 1959, Art. 30 (isotropic: w_c = 0.00406 q a^4/D).
!>
!> 3. Cylindrical bending of a long uniformly loaded strip of span l whose
!>    edges cannot move towards each other, simply supported (TWK Art. 2)
!>    or built in (TWK Art. 3). D = E h^3/(12 (1 - nu^2)); the axial force
!>    S per unit width sets u^2 = S l^2/(4 D). With xi from the centre,
!>    s = xi/l in [-1/2, 1/2] and c = 3 (1 - nu^2) Q/(2 u^2),
!>    Q = q l^4/(E h^4), the deflection D w'''' - S w'' = q is
!>        w/h = A cosh(2 u s) + B - c s^2,
!>        simply supported: A = c/(2 u^2 cosh u),   B = c/4 - c/(2 u^2),
!>        built in:         A = c/(2 u sinh u),     B = c/4 - c/(2 u tanh u),
!>    and the immovable edges require the extension S (1 - nu^2)/(E h) to
!>    equal (1/2l) int w'^2 dx, i.e. u^2 = (3/2) int (d(w/h)/ds)^2 ds, which
!>    gives Q explicitly in u:
!>        Q^2 (1 - nu^2)^2 = 8 u^6 / (27 G(u)),
!>        G(u) = 4 u^2 a^2 (sinh 2u/(4u) - 1/2) - 8 u a (cosh u/(2u) - sinh u/(2u^2)) + 1/3,
!>    a = A/c. For the simply supported strip this is TWK's eq. (10), Art. 2:
!>        E^2 h^8/((1-nu^2)^2 q^2 l^8) = 135/16 tanh u/u^9 + 27/16 tanh^2 u/u^8
!>                                        - 135/16 1/u^8 + 9/8 1/u^6,
!>    and for the built-in strip TWK's eq. (e), Art. 3:
!>        E^2 h^8/((1-nu^2)^2 q^2 l^8) = -81/16 1/(u^7 tanh u) - 27/16 1/(u^6 sinh^2 u)
!>                                        + 27/4 1/u^8 + 9/8 1/u^6;
!>    strip_deflection solves Q(u) = Q for u by bisection and returns the
!>    centre deflection w0/h = A + B. G has a cancellation of order u^-6
!>    (rounding error about 1e-16 u^-6 relative), so u is kept >=
!>    strip_u_min = 0.05 (Q >= 0.13 simply supported, 0.65 built in); TWK's
!>    printed forms cancel worse (u^-9).
!>
!> 4. Hertz impact of a rigid mass m at speed v on a rigid flat target
!>    through the contact law F = k alpha^1.5 (K. L. Johnson, Contact
!>    Mechanics, CUP 1985, section 11.4): energy gives the largest
!>    indentation alpha_m = (5 m v^2/(4 k))^(2/5), F_m = k alpha_m^1.5, and
!>    the time to reach it t_1 = (alpha_m/v) int_0^1 (1 - x^(5/2))^(-1/2) dx
!>    = (alpha_m/v) Gamma(7/5) Gamma(1/2)/Gamma(9/10) = 1.4716 alpha_m/v;
!>    the elastic contact lasts 2 t_1 = 2.9432 alpha_m/v.
!>    With the paper's unloading law F = F_m ((alpha - alpha_0)/(alpha_m - alpha_0))^q
!>    (eq. 11-12, alpha_0 = beta (alpha_m - alpha_p) when alpha_m > alpha_p)
!>    the energy given back is F_m (alpha_m - alpha_0)/(q + 1), so the
!>    coefficient of restitution is
!>        e = sqrt(5 (alpha_m - alpha_0) / (2 (q + 1) alpha_m)),
!>    the unloading lasts sqrt(m (q+1)(alpha_m - alpha_0)/(2 F_m)) *
!>    Gamma(1 + 1/p) Gamma(1/2)/Gamma(1/p + 1/2) with p = q + 1, and the
!>    energy dissipated (the area of the force-indentation loop) is
!>    (1 - e^2) m v^2/2.
!>
!> 5. Ply stresses of the Navier solution (item 1) under the sinusoidal
!>    load q0 sin(pi x/a) sin(pi y/b), symmetric cross-ply (Qbar16 = Qbar26
!>    = 0, B = 0): with W, X, Y of the (1, 1) term, kappa_x = -alpha X s c',
!>    ... (s = sin, c = cos of alpha x and beta y), the in-plane stresses
!>    of ply k are exact, eq. (3): sigma_x = z (Qbar11 kappa_x + Qbar12 kappa_y),
!>    sigma_y = z (Qbar12 kappa_x + Qbar22 kappa_y), tau_xy = z Qbar66 kappa_xy;
!>    the transverse shear from the first two equations of equilibrium
!>    (eq. 7, static), integrated from z = -h/2 ply by ply:
!>        tau_xz(z) = -int zeta (Qbar11 kappa_x,x + Qbar12 kappa_y,x + Qbar66 kappa_xy,y) dzeta,
!>        tau_yz(z) = -int zeta (Qbar66 kappa_xy,x + Qbar12 kappa_x,y + Qbar22 kappa_y,y) dzeta,
!>    (Reddy 2004, section 7.3.3, the same recovery); it vanishes on both
!>    faces, since N = 0. Written out here with its own rotation into the
!>    ply axes, independent of src/strength/ply_stress.f90.
!>
!> 6. The isotropic plate under the same load, Kirchhoff's resultants
!>    (Timoshenko & Woinowsky-Krieger, Art. 28): with
!>    W = q0/(D (alpha^2 + beta^2)^2),
!>        M_x = D (alpha^2 + nu beta^2) W s s,  M_y = D (nu alpha^2 + beta^2) W s s,
!>        M_xy = -D (1 - nu) alpha beta W c c,
!>        Q_x = D alpha (alpha^2 + beta^2) W c s,  Q_y = D beta (alpha^2 + beta^2) W s c
!>    (the signs of this code: z and w along the load, kappa_x = psi_x,x),
!>    and the stresses of a homogeneous plate sigma = 12 M z/h^3,
!>    tau_xz = 3 Q_x/(2 h) (1 - 4 z^2/h^2). For a simply supported polygonal
!>    isotropic plate the first-order theory's moments and shear forces are
!>    Kirchhoff's (its rotations are -grad w of the classical plate: C. M.
!>    Wang, J. N. Reddy, K. H. Lee, Shear Deformable Beams and Plates,
!>    Elsevier 2000, ch. 7), so these are exact for the FE's theory too.
!>
!> Units: SI throughout (m, N, Pa, kg, s, rad/s).
module reference_solutions
   use kinds, only: dp, pi
   use materials, only: laminate_t, lamina_t, lamina_qbar
   implicit none
   private
   public :: navier_series_t, navier_fsdt, navier_fsdt_static, navier_static_centre, navier_step_centre, &
             navier_frequencies, navier_clpt_centre, &
             strip_load_parameter, strip_deflection, strip_twk_rhs, strip_u_min, &
             hertz_impact_t, hertz_impact, navier_sinusoidal_ply_stresses, isotropic_sinusoidal_stresses, &
             load_uniform, load_sinusoidal, load_central_force, &
             edge_simply_supported, edge_clamped

   !> Load cases of the Navier solutions.
   integer, parameter :: load_uniform = 1, load_sinusoidal = 2, load_central_force = 3
   !> Edges of the strip.
   integer, parameter :: edge_simply_supported = 1, edge_clamped = 2
   !> Smallest u of the strip solution (see the module header, item 3).
   real(dp), parameter :: strip_u_min = 0.05_dp
   !> Largest u searched (Q far beyond any plate problem).
   real(dp), parameter :: strip_u_max = 60.0_dp
   !> Bisection steps of the strip solution (u to the last bit).
   integer, parameter :: strip_bisections = 200

   !> The terms of a Navier series: for every (m, n) kept and each of its
   !> three FSDT modes k, the circular frequency and the contribution to
   !> the centre deflection, w_c(t) = sum c (1 - cos omega t).
   type :: navier_series_t
      integer :: nterm = 0                       !< terms kept (3 per (m, n))
      integer, allocatable :: m(:), n(:)         !< half-wave numbers of each term
      real(dp), allocatable :: omega(:)          !< circular frequency (rad/s)
      real(dp), allocatable :: c(:)              !< static centre-deflection share (m)
      real(dp), allocatable :: w_mn(:)           !< static centre deflection of each (m, n), direct solve (m)
   end type navier_series_t

   !> Hertz impact of a rigid mass on a rigid target (module header, item 4).
   type :: hertz_impact_t
      real(dp) :: alpha_m = 0.0_dp      !< largest indentation (m)
      real(dp) :: f_m = 0.0_dp          !< largest force (N)
      real(dp) :: t_load = 0.0_dp       !< time from first touch to alpha_m (s)
      real(dp) :: t_unload = 0.0_dp     !< time from alpha_m to separation (s)
      real(dp) :: duration = 0.0_dp     !< contact duration t_load + t_unload (s)
      real(dp) :: alpha_0 = 0.0_dp      !< permanent indentation (m)
      real(dp) :: restitution = 0.0_dp  !< rebound speed / impact speed (-)
      real(dp) :: dissipated = 0.0_dp   !< area of the force-indentation loop (J)
   end type hertz_impact_t

   ! LAPACK: generalized symmetric-definite eigenproblem of a dense matrix,
   ! and a symmetric positive definite solve.
   interface
      subroutine dposv(uplo, n, nrhs, a, lda, b, ldb, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, nrhs, lda, ldb
         real(dp), intent(inout) :: a(lda, *), b(ldb, *)
         integer, intent(out) :: info
      end subroutine dposv
      subroutine dsygv(itype, jobz, uplo, n, a, lda, b, ldb, w, work, lwork, info)
         import :: dp
         integer, intent(in) :: itype, n, lda, ldb, lwork
         character, intent(in) :: jobz, uplo
         real(dp), intent(inout) :: a(lda, *), b(ldb, *)
         real(dp), intent(out) :: w(*), work(*)
         integer, intent(out) :: info
      end subroutine dsygv
   end interface

contains

   ! ===================================================== Navier, FSDT

   !> The FSDT Navier series of a simply supported a x b plate of laminate
   !> lmt (specially orthotropic: its A16, A26, D16, D26, Abar45, B are not
   !> used) under the load `load` of magnitude q0 (Pa; N for a central
   !> force), every odd m, n <= mmax for uniform and central loads, (1, 1)
   !> alone for the sinusoidal load. Module header, item 1.
   subroutine navier_fsdt(lmt, a, b, load, q0, mmax, series, stat, errmsg)
      type(laminate_t), intent(in) :: lmt          !< D, Abar, P, I used
      real(dp), intent(in) :: a, b                 !< plate size along x, y (m)
      integer, intent(in) :: load                  !< load_uniform, load_sinusoidal or load_central_force
      real(dp), intent(in) :: q0                   !< pressure (Pa) or force (N)
      integer, intent(in) :: mmax                  !< largest half-wave number kept (odd)
      type(navier_series_t), intent(out) :: series !< the terms
      integer, intent(out) :: stat                 !< 0 on success
      character(len=*), intent(inout) :: errmsg    !< reason on failure
      integer :: m, n, nmax, t, pair
      real(dp) :: qmn, s_mn, omega2(3), phi(3,3), x(3)

      stat = 0
      if (all(load /= [load_uniform, load_sinusoidal, load_central_force])) then
         stat = 1
         errmsg = 'navier_fsdt: unknown load case'
         return
      end if
      nmax = merge(1, mmax, load == load_sinusoidal)
      t = 3*((nmax + 1)/2)**2
      allocate (series%m(t), series%n(t), series%omega(t), series%c(t), series%w_mn(t/3))
      t = 0
      pair = 0
      half_waves_x: do m = 1, nmax, 2
         half_waves_y: do n = 1, nmax, 2
            qmn = load_coefficient(load, q0, a, b, m, n)
            s_mn = real((-1)**((m - 1)/2 + (n - 1)/2), dp)   ! sin(m pi/2) sin(n pi/2)
            call navier_modes(lmt, m*pi/a, n*pi/b, omega2, phi, stat, errmsg)
            if (stat /= 0) return
            series%m(t+1:t+3) = m
            series%n(t+1:t+3) = n
            series%omega(t+1:t+3) = sqrt(omega2)
            series%c(t+1:t+3) = s_mn*phi(1, :)**2*qmn/omega2
            t = t + 3
            call navier_static(lmt, m*pi/a, n*pi/b, qmn, x, stat, errmsg)
            if (stat /= 0) return
            pair = pair + 1
            series%w_mn(pair) = s_mn*x(1)
         end do half_waves_y
      end do half_waves_x
      series%nterm = t
   end subroutine navier_fsdt

   !> Static centre deflection (m) of the FSDT Navier solution, odd m, n <=
   !> mmax (the sinusoidal load: (1, 1) alone): the direct solves of
   !> navier_fsdt without the modes.
   subroutine navier_fsdt_static(lmt, a, b, load, q0, mmax, w, stat, errmsg)
      type(laminate_t), intent(in) :: lmt          !< D, Abar used
      real(dp), intent(in) :: a, b                 !< plate size along x, y (m)
      integer, intent(in) :: load                  !< load_uniform, load_sinusoidal or load_central_force
      real(dp), intent(in) :: q0                   !< pressure (Pa) or force (N)
      integer, intent(in) :: mmax                  !< largest half-wave number kept (odd)
      real(dp), intent(out) :: w                   !< centre deflection (m)
      integer, intent(out) :: stat                 !< 0 on success
      character(len=*), intent(inout) :: errmsg    !< reason on failure
      real(dp) :: x(3), qmn
      integer :: m, n, nmax
      w = 0.0_dp
      stat = 0
      nmax = mmax
      if (load == load_sinusoidal) nmax = 1
      half_waves_x: do m = 1, nmax, 2
         half_waves_y: do n = 1, nmax, 2
            qmn = load_coefficient(load, q0, a, b, m, n)
            call navier_static(lmt, m*pi/a, n*pi/b, qmn, x, stat, errmsg)
            if (stat /= 0) return
            w = w + real((-1)**((m - 1)/2 + (n - 1)/2), dp)*x(1)
         end do half_waves_y
      end do half_waves_x
   end subroutine navier_fsdt_static

   !> Static centre deflection of the series (m).
   pure function navier_static_centre(series) result(w)
      type(navier_series_t), intent(in) :: series  !< from navier_fsdt
      real(dp) :: w
      w = sum(series%w_mn)
   end function navier_static_centre

   !> Centre deflection (m) at time t (s) after the load was applied.
   pure function navier_step_centre(series, t) result(w)
      type(navier_series_t), intent(in) :: series  !< from navier_fsdt
      real(dp), intent(in) :: t                    !< time since the load was applied (s)
      real(dp) :: w
      w = sum(series%c(:series%nterm)*(1.0_dp - cos(series%omega(:series%nterm)*t)))
   end function navier_step_centre

   !> The three FSDT circular frequencies (rad/s, ascending) of the
   !> half-wave numbers (m, n): flexural, then two thickness-shear modes.
   subroutine navier_frequencies(lmt, a, b, m, n, omega, stat, errmsg)
      type(laminate_t), intent(in) :: lmt          !< laminate
      real(dp), intent(in) :: a, b                 !< plate size (m)
      integer, intent(in) :: m, n                  !< half-wave numbers along x, y
      real(dp), intent(out) :: omega(3)            !< circular frequencies (rad/s)
      integer, intent(out) :: stat                 !< 0 on success
      character(len=*), intent(inout) :: errmsg    !< reason on failure
      real(dp) :: omega2(3), phi(3,3)
      call navier_modes(lmt, m*pi/a, n*pi/b, omega2, phi, stat, errmsg)
      omega = sqrt(max(omega2, 0.0_dp))
   end subroutine navier_frequencies

   !> S {W X Y} = {q 0 0} for one (alpha, beta) (LAPACK dposv).
   subroutine navier_static(lmt, alpha, beta, q, x, stat, errmsg)
      type(laminate_t), intent(in) :: lmt
      real(dp), intent(in) :: alpha, beta          ! m pi/a, n pi/b (1/m)
      real(dp), intent(in) :: q                    ! load coefficient Q_mn (Pa)
      real(dp), intent(out) :: x(3)                ! W (m), X, Y (rad)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      real(dp) :: s(3,3)
      integer :: info
      s = navier_stiffness(lmt, alpha, beta)
      x = [q, 0.0_dp, 0.0_dp]
      call dposv('U', 3, 1, s, 3, x, 3, info)
      stat = 0
      if (info /= 0) then
         stat = 1
         write (errmsg, '(a,i0)') 'navier_static: LAPACK dposv failed, info = ', info
      end if
   end subroutine navier_static

   !> The 3 x 3 stiffness [S] of one (alpha, beta) (module header, item 1).
   pure function navier_stiffness(lmt, alpha, beta) result(s)
      type(laminate_t), intent(in) :: lmt
      real(dp), intent(in) :: alpha, beta          ! m pi/a, n pi/b (1/m)
      real(dp) :: s(3,3)
      real(dp) :: a44, a55
      a44 = lmt%as(1,1);  a55 = lmt%as(2,2)
      s(1,1) = a55*alpha**2 + a44*beta**2
      s(1,2) = a55*alpha
      s(1,3) = a44*beta
      s(2,2) = lmt%d(1,1)*alpha**2 + lmt%d(3,3)*beta**2 + a55
      s(2,3) = (lmt%d(1,2) + lmt%d(3,3))*alpha*beta
      s(3,3) = lmt%d(3,3)*alpha**2 + lmt%d(2,2)*beta**2 + a44
      s(2,1) = s(1,2);  s(3,1) = s(1,3);  s(3,2) = s(2,3)
   end function navier_stiffness

   !> S phi = omega^2 M phi for one (alpha, beta), phi M-orthonormal (LAPACK dsygv).
   subroutine navier_modes(lmt, alpha, beta, omega2, phi, stat, errmsg)
      type(laminate_t), intent(in) :: lmt
      real(dp), intent(in) :: alpha, beta          ! m pi/a, n pi/b (1/m)
      real(dp), intent(out) :: omega2(3)           ! squared circular frequencies (rad^2/s^2)
      real(dp), intent(out) :: phi(3,3)            ! modes in columns (W, X, Y)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer, parameter :: lwork = 64
      real(dp) :: s(3,3), mm(3,3), work(lwork)
      integer :: info

      s = navier_stiffness(lmt, alpha, beta)
      mm = 0.0_dp
      mm(1,1) = lmt%p;  mm(2,2) = lmt%i;  mm(3,3) = lmt%i
      call dsygv(1, 'V', 'U', 3, s, 3, mm, 3, omega2, work, lwork, info)
      stat = 0
      if (info /= 0) then
         stat = 1
         write (errmsg, '(a,i0)') 'navier_modes: LAPACK dsygv failed, info = ', info
         return
      end if
      phi = s
   end subroutine navier_modes

   ! ===================================================== ply stresses

   !> Item 5: the ply stresses (s11, s22, t12, t23, t13) in the material
   !> axes, sigma(:, f, k) on face f (1 bottom, 2 top) of ply k, of the
   !> Navier solution under the sinusoidal load q0 at (x, y), 0 <= x <= a.
   subroutine navier_sinusoidal_ply_stresses(lam, angles, lmt, a, b, q0, x, y, sigma, stat, errmsg)
      type(lamina_t), intent(in) :: lam            !< the lamina
      real(dp), intent(in) :: angles(:)            !< ply angles (0 or 90), bottom to top (deg)
      type(laminate_t), intent(in) :: lmt          !< its laminate (D, Abar; h)
      real(dp), intent(in) :: a, b, q0             !< plate (m), load amplitude (Pa)
      real(dp), intent(in) :: x, y                 !< point, from the corner (m)
      real(dp), intent(out) :: sigma(:,:,:)        !< (5, 2, nply) (Pa)
      integer, intent(out) :: stat                 !< 0 on success
      character(len=*), intent(inout) :: errmsg    !< reason on failure
      real(dp) :: wxy(3), al, be, sx, cx, sy, cy, kap(3), kx(3), ky(3), qb(3,3), z0, z1, z, txz, tyz, &
                  txz0, tyz0, sxyz(3), c, s
      integer :: k, f, n
      al = pi/a;  be = pi/b
      call navier_static(lmt, al, be, q0, wxy, stat, errmsg)
      if (stat /= 0) return
      sx = sin(al*x);  cx = cos(al*x);  sy = sin(be*y);  cy = cos(be*y)
      associate (xx => wxy(2), yy => wxy(3))
         kap = [-al*xx*sx*sy, -be*yy*sx*sy, (be*xx + al*yy)*cx*cy]
         kx = [-al**2*xx*cx*sy, -al*be*yy*cx*sy, -al*(be*xx + al*yy)*sx*cy]     ! d kappa/dx
         ky = [-al*be*xx*sx*cy, -be**2*yy*sx*cy, -be*(be*xx + al*yy)*cx*sy]     ! d kappa/dy
      end associate
      n = size(angles)
      txz0 = 0.0_dp;  tyz0 = 0.0_dp
      plies: do k = 1, n
         qb = lamina_qbar(lam, angles(k))
         z0 = -0.5_dp*lmt%h + real(k - 1, dp)*lmt%h/real(n, dp)
         z1 = z0 + lmt%h/real(n, dp)
         c = cos(angles(k)*pi/180.0_dp);  s = sin(angles(k)*pi/180.0_dp)
         faces: do f = 1, 2
            z = merge(z0, z1, f == 1)
            sxyz = z*[qb(1,1)*kap(1) + qb(1,2)*kap(2), qb(1,2)*kap(1) + qb(2,2)*kap(2), qb(3,3)*kap(3)]
            txz = txz0 - 0.5_dp*(z**2 - z0**2)*(qb(1,1)*kx(1) + qb(1,2)*kx(2) + qb(3,3)*ky(3))
            tyz = tyz0 - 0.5_dp*(z**2 - z0**2)*(qb(3,3)*kx(3) + qb(1,2)*ky(1) + qb(2,2)*ky(2))
            sigma(1, f, k) = c*c*sxyz(1) + s*s*sxyz(2) + 2.0_dp*c*s*sxyz(3)
            sigma(2, f, k) = s*s*sxyz(1) + c*c*sxyz(2) - 2.0_dp*c*s*sxyz(3)
            sigma(3, f, k) = -c*s*sxyz(1) + c*s*sxyz(2) + (c*c - s*s)*sxyz(3)
            sigma(4, f, k) = -s*txz + c*tyz
            sigma(5, f, k) = c*txz + s*tyz
         end do faces
         txz0 = txz;  tyz0 = tyz
      end do plies
   end subroutine navier_sinusoidal_ply_stresses

   !> Item 6: (sigma_x, sigma_y, tau_xy, tau_yz, tau_xz) of the isotropic
   !> plate (E, nu, h) under the sinusoidal load q0 at (x, y, z), x, y from
   !> the corner.
   pure function isotropic_sinusoidal_stresses(e, nu, h, a, b, q0, x, y, z) result(st)
      real(dp), intent(in) :: e, nu, h, a, b, q0, x, y, z
      real(dp) :: st(5)
      real(dp) :: d, al, be, w, mx, my, mxy, qx, qy
      d = e*h**3/(12.0_dp*(1.0_dp - nu**2))
      al = pi/a;  be = pi/b
      w = q0/(d*(al**2 + be**2)**2)
      mx = d*(al**2 + nu*be**2)*w*sin(al*x)*sin(be*y)
      my = d*(nu*al**2 + be**2)*w*sin(al*x)*sin(be*y)
      mxy = -d*(1.0_dp - nu)*al*be*w*cos(al*x)*cos(be*y)
      qx = d*al*(al**2 + be**2)*w*cos(al*x)*sin(be*y)
      qy = d*be*(al**2 + be**2)*w*sin(al*x)*cos(be*y)
      st = [12.0_dp*mx*z/h**3, 12.0_dp*my*z/h**3, 12.0_dp*mxy*z/h**3, &
            1.5_dp*qy/h*(1.0_dp - 4.0_dp*z**2/h**2), 1.5_dp*qx/h*(1.0_dp - 4.0_dp*z**2/h**2)]
   end function isotropic_sinusoidal_stresses

   !> The load's Fourier coefficient Q_mn (Pa) of sin(alpha x) sin(beta y)
   !> (module header, item 1; Reddy 2004, section 7.3): uniform q0 (Pa)
   !> 16 q0/(pi^2 m n); sinusoidal q0 (Pa), (1, 1) only; a central force q0
   !> (N) 4 q0/(a b) sin(m pi/2) sin(n pi/2).
   pure real(dp) function load_coefficient(load, q0, a, b, m, n) result(qmn)
      integer, intent(in) :: load          !< load_uniform, load_sinusoidal or load_central_force
      real(dp), intent(in) :: q0           !< pressure (Pa) or force (N)
      real(dp), intent(in) :: a, b         !< plate size (m)
      integer, intent(in) :: m, n          !< half-wave numbers (odd)
      select case (load)
      case (load_uniform)
         qmn = 16.0_dp*q0/(pi**2*real(m*n, dp))
      case (load_sinusoidal)
         qmn = q0
      case default   ! central force
         qmn = 4.0_dp*q0/(a*b)*real((-1)**((m - 1)/2 + (n - 1)/2), dp)
      end select
   end function load_coefficient

   ! ===================================================== Navier, CLPT

   !> Classical-plate-theory centre deflection (m) of the simply supported
   !> specially orthotropic plate, odd m, n <= mmax (module header, item 2).
   pure function navier_clpt_centre(lmt, a, b, load, q0, mmax) result(w)
      type(laminate_t), intent(in) :: lmt   !< D used
      real(dp), intent(in) :: a, b          !< plate size (m)
      integer, intent(in) :: load           !< load case
      real(dp), intent(in) :: q0            !< pressure (Pa) or force (N)
      integer, intent(in) :: mmax           !< largest half-wave number kept
      real(dp) :: w
      real(dp) :: qmn, rm, rn, den
      integer :: m, n, nmax
      w = 0.0_dp
      nmax = mmax
      if (load == load_sinusoidal) nmax = 1
      do m = 1, nmax, 2
         do n = 1, nmax, 2
            qmn = load_coefficient(load, q0, a, b, m, n)
            rm = real(m, dp)/a;  rn = real(n, dp)/b
            den = pi**4*(lmt%d(1,1)*rm**4 + 2.0_dp*(lmt%d(1,2) + 2.0_dp*lmt%d(3,3))*rm**2*rn**2 &
                  + lmt%d(2,2)*rn**4)
            w = w + real((-1)**((m - 1)/2 + (n - 1)/2), dp)*qmn/den
         end do
      end do
   end function navier_clpt_centre

   ! ===================================================== strip (TWK Arts. 2-3)

   !> The load parameter Q = q l^4/(E h^4) at which the strip's membrane
   !> parameter is u, and the centre deflection w0/h there (module header,
   !> item 3).
   pure subroutine strip_load_parameter(edge, nu, u, q, w0_h)
      integer, intent(in) :: edge          !< edge_simply_supported or edge_clamped
      real(dp), intent(in) :: nu           !< Poisson's ratio (-)
      real(dp), intent(in) :: u            !< u = (l/2) sqrt(S/D) (-), >= strip_u_min
      real(dp), intent(out) :: q           !< Q = q l^4/(E h^4) (-)
      real(dp), intent(out) :: w0_h        !< centre deflection / thickness (-)
      real(dp) :: ar, g, c, bb
      if (edge == edge_clamped) then
         ar = 1.0_dp/(2.0_dp*u*sinh(u))
         bb = 0.25_dp - 1.0_dp/(2.0_dp*u*tanh(u))
      else
         ar = 1.0_dp/(2.0_dp*u**2*cosh(u))
         bb = 0.25_dp - 1.0_dp/(2.0_dp*u**2)
      end if
      g = 4.0_dp*u**2*ar**2*(sinh(2.0_dp*u)/(4.0_dp*u) - 0.5_dp) &
          - 8.0_dp*u*ar*(cosh(u)/(2.0_dp*u) - sinh(u)/(2.0_dp*u**2)) + 1.0_dp/3.0_dp
      q = sqrt(8.0_dp*u**6/(27.0_dp*g))/(1.0_dp - nu**2)
      c = 3.0_dp*(1.0_dp - nu**2)*q/(2.0_dp*u**2)
      w0_h = c*(ar + bb)
   end subroutine strip_load_parameter

   !> TWK's right-hand side E^2 h^8/((1-nu^2)^2 q^2 l^8) as printed in
   !> Art. 2 eq. (10) (simply supported) and Art. 3 (built in), for
   !> checking strip_load_parameter against the book.
   pure function strip_twk_rhs(edge, u) result(r)
      integer, intent(in) :: edge   !< edge_simply_supported or edge_clamped
      real(dp), intent(in) :: u     !< membrane parameter (-)
      real(dp) :: r
      if (edge == edge_clamped) then
         r = -81.0_dp/(16.0_dp*u**7*tanh(u)) - 27.0_dp/(16.0_dp*u**6*sinh(u)**2) &
             + 27.0_dp/(4.0_dp*u**8) + 9.0_dp/(8.0_dp*u**6)
      else
         r = 135.0_dp/16.0_dp*tanh(u)/u**9 + 27.0_dp/16.0_dp*tanh(u)**2/u**8 &
             - 135.0_dp/16.0_dp/u**8 + 9.0_dp/8.0_dp/u**6
      end if
   end function strip_twk_rhs

   !> Centre deflection w0/h of the strip under Q = q l^4/(E h^4): bisection
   !> on u in [strip_u_min, strip_u_max] (Q increases with u). stat = 1 when
   !> Q is outside the range this covers.
   subroutine strip_deflection(edge, nu, q, w0_h, u, stat, errmsg)
      integer, intent(in) :: edge                  !< edge_simply_supported or edge_clamped
      real(dp), intent(in) :: nu                   !< Poisson's ratio (-)
      real(dp), intent(in) :: q                    !< Q = q l^4/(E h^4) (-)
      real(dp), intent(out) :: w0_h                !< centre deflection / thickness (-)
      real(dp), intent(out) :: u                   !< membrane parameter (-)
      integer, intent(out) :: stat                 !< 0 on success
      character(len=*), intent(inout) :: errmsg    !< reason on failure
      real(dp) :: lo, hi, q_lo, q_hi, q_mid, w
      integer :: it
      stat = 0
      lo = strip_u_min;  hi = strip_u_max
      call strip_load_parameter(edge, nu, lo, q_lo, w)
      call strip_load_parameter(edge, nu, hi, q_hi, w)
      if (.not. (q >= q_lo .and. q <= q_hi)) then
         stat = 1
         write (errmsg, '(a,es10.3,a,es10.3,a,es10.3,a)') 'strip_deflection: Q = ', q, &
            ' outside [', q_lo, ', ', q_hi, '] covered'
         return
      end if
      bisection: do it = 1, strip_bisections
         u = 0.5_dp*(lo + hi)
         call strip_load_parameter(edge, nu, u, q_mid, w)
         if (q_mid < q) then
            lo = u
         else
            hi = u
         end if
         if (hi - lo <= 2.0_dp*spacing(u)) exit bisection
      end do bisection
      u = 0.5_dp*(lo + hi)
      call strip_load_parameter(edge, nu, u, q_mid, w0_h)
   end subroutine strip_deflection

   ! ===================================================== Hertz impact

   !> Impact of a rigid mass on a rigid target through the law
   !> F = k alpha^1.5, with the paper's unloading (module header, item 4).
   !> beta = 0 and q = 1.5 give the elastic Hertz impact.
   pure function hertz_impact(mass, v, k, q, alpha_p, beta) result(r)
      real(dp), intent(in) :: mass      !< impactor mass (kg)
      real(dp), intent(in) :: v         !< impact speed (m/s)
      real(dp), intent(in) :: k         !< contact stiffness (N/m^1.5)
      real(dp), intent(in) :: q         !< unloading exponent (-)
      real(dp), intent(in) :: alpha_p   !< critical indentation (m)
      real(dp), intent(in) :: beta      !< permanent indentation ratio (-)
      type(hertz_impact_t) :: r
      real(dp) :: p
      r%alpha_m = (5.0_dp*mass*v**2/(4.0_dp*k))**0.4_dp
      r%f_m = k*r%alpha_m**1.5_dp
      ! int_0^1 (1 - x^(5/2))^(-1/2) dx = Gamma(7/5) Gamma(1/2) / Gamma(9/10)
      r%t_load = r%alpha_m/v*gamma(1.4_dp)*sqrt(pi)/gamma(0.9_dp)
      r%alpha_0 = 0.0_dp
      if (r%alpha_m > alpha_p) r%alpha_0 = beta*(r%alpha_m - alpha_p)
      p = q + 1.0_dp
      r%t_unload = sqrt(mass*p*(r%alpha_m - r%alpha_0)/(2.0_dp*r%f_m)) &
                   *gamma(1.0_dp + 1.0_dp/p)*sqrt(pi)/gamma(1.0_dp/p + 0.5_dp)
      r%duration = r%t_load + r%t_unload
      r%restitution = sqrt(5.0_dp*(r%alpha_m - r%alpha_0)/(2.0_dp*p*r%alpha_m))
      r%dissipated = (1.0_dp - r%restitution**2)*0.5_dp*mass*v**2
   end function hertz_impact

end module reference_solutions
