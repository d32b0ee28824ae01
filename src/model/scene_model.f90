!> Model only what the scene requires: the choices the code makes before a
!> run and the scene report that shows how far the scene is from each
!> simplification.
!>  - the modelled domain: a quarter or a half plate where the laminate
!>    and the impact point are mirror-symmetric (the paper's section 3.1;
!>    above laminate_couplings);
!>  - the theory: von Karman's where the static estimate of w/h exceeds
!>    wh_nonlinear (above choose_theory), from the energy balance of a
!>    quasi-static impact with the loading law, eq. (11) (above energy_balance);
!>  - the Hertz contact radius against the element size, for the paper's
!>    point force (above write_scene_report).
!> The shear correction factors come from src/model/shear_correction.f90.
!> More: docs/MODEL.md, "How the code decides"; the measurements:
!> docs/validation/model_choice.md.
module scene_model
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use kinds, only: dp, msg_len
   use materials, only: lamina_t, laminate_t, laminate_from_layup
   use shear_correction, only: whitney_shear_factors
   use deck_schema, only: deck_t, max_word_len
   use mesh, only: mesh_t, apply_boundary, nfe
   use element_matrices, only: element_geometry_t, element_stiffness
   use global_matrix, only: global_matrix_t, global_init, global_zero, global_assemble, global_factor, &
      global_solve, global_release, global_copy
   use storage_choice, only: resolve_storage, sparse_crossover
   implicit none
   private
   public :: scene_t, ncouplings, coupling_names, coupling_tol, wh_nonlinear, model_laminate, &
             choose_domain, energy_balance, choose_theory, write_scene_report, theory_warning, &
             point_stiffness, impact_element_size, bending_deflection, choose_storage

   !> Couplings below this fraction of the diagonal terms are rounding (-).
   real(dp), parameter :: coupling_tol = 1.0e-9_dp
   !> w/h above which the von Karman terms are needed (above choose_theory) (-).
   real(dp), parameter :: wh_nonlinear = 0.2_dp
   !> Contact radius / element size above which the report warns (above write_scene_report) (-).
   real(dp), parameter :: max_radius_ratio = 0.5_dp
   !> The couplings a mirror image reverses, each relative to its diagonal terms.
   integer, parameter :: ncouplings = 7
   character(len=*), parameter :: coupling_names(ncouplings) = [character(len=26) :: &
      'D16/D11', 'D26/D22', 'A16/A11', 'A26/A22', 'B16/sqrt(A11 D11)', 'B26/sqrt(A22 D22)', &
      'Abar45/sqrt(Abar44 Abar55)']
   !> The first n_bend_twist couplings (D16, D26) may be averaged away (section 3.1).
   integer, parameter :: n_bend_twist = 2
   !> Bisection steps of the energy balance: 2^-200 of the bracket, far below rounding.
   integer, parameter :: max_bisection = 200
   !> Text length of the keywords (those of the deck).
   integer, parameter :: word_len = max_word_len
   !> Rigid-body terms of a plane w = c1 + c2 x + c3 y, at most.
   integer, parameter :: max_plane_terms = 3

   ! LAPACK: least squares by QR (bending_deflection).
   interface
      !> Minimises || b - A x || for a full-rank m x n matrix A, m >= n.
      subroutine dgels(trans, m, n, nrhs, a, lda, b, ldb, work, lwork, info)
         import :: dp
         character, intent(in) :: trans
         integer, intent(in) :: m, n, nrhs, lda, ldb, lwork
         real(dp), intent(inout) :: a(lda, *), b(ldb, *)
         real(dp), intent(out) :: work(*)
         integer, intent(out) :: info
      end subroutine dgels
   end interface

   !> The scene's choices, their reasons and its distance from each simplification.
   type :: scene_t
      real(dp) :: k4 = 0.0_dp, k5 = 0.0_dp          !< shear correction factors used (-)
      logical :: k_whitney = .false.                !< k4, k5 computed by Whitney's method
      real(dp) :: couplings(ncouplings) = 0.0_dp    !< |coupling| / diagonal, coupling_names order (-)
      character(len=word_len) :: domain = ''        !< 'quarter', 'half', 'full' or 'strip'
      logical :: averaged = .false.                 !< D16 = D26 = 0 set on the model (section 3.1)
      character(len=msg_len) :: domain_reason = ''  !< why that domain
      real(dp) :: h = 0.0_dp                        !< plate thickness (m)
      real(dp) :: stiffness = 0.0_dp                !< static stiffness K at the impact point (N/m)
      character(len=msg_len) :: stiffness_note = '' !< how K was found
      real(dp) :: energy = 0.0_dp                   !< impactor energy 1/2 m v^2 (J)
      real(dp) :: force = 0.0_dp                    !< estimated peak force (N)
      real(dp) :: deflection = 0.0_dp               !< estimated deflection at the impact point (m)
      real(dp) :: indentation = 0.0_dp              !< estimated indentation (m)
      real(dp) :: contact_radius = 0.0_dp           !< Hertz contact radius at that force (m)
      logical :: point_load = .false.               !< the paper's point force (&contact load = 'point')
      real(dp) :: element_size(2) = 0.0_dp          !< sides along x, y of the element at the impact point (m)
      real(dp) :: impactor_mass = 0.0_dp            !< m (kg)
      real(dp) :: plate_mass = 0.0_dp               !< rho h a b, the whole plate (kg)
      character(len=word_len) :: theory = ''        !< 'linear' or 'nonlinear'
      character(len=msg_len) :: theory_reason = ''  !< why that theory
      character(len=word_len) :: storage = ''       !< storage of the matrices: 'band', 'skyline' or 'sparse'
      character(len=msg_len) :: storage_reason = '' !< why that storage
   end type scene_t

contains

   !> The laminate of the deck (eq. 6, 9) with its shear correction factors:
   !> the deck's k4, k5, or Whitney's when the deck does not give them.
   pure subroutine model_laminate(deck, lmt, scene)
      type(deck_t), intent(in) :: deck           !< the deck
      type(laminate_t), intent(out) :: lmt       !< the laminate as laid up
      type(scene_t), intent(inout) :: scene      !< k4, k5, k_whitney, couplings, h, masses set
      type(lamina_t) :: lam
      real(dp) :: k4w, k5w

      lam = lamina_t(deck%e1, deck%e2, deck%g12, deck%g13, deck%g23, deck%nu12, deck%rho)
      call whitney_shear_factors(lam, deck%angles, deck%h, k4w, k5w)
      scene%k_whitney = ieee_is_nan(deck%k4) .or. ieee_is_nan(deck%k5)    ! not given (src/deck/deck_schema.f90)
      scene%k4 = merge(k4w, deck%k4, ieee_is_nan(deck%k4))
      scene%k5 = merge(k5w, deck%k5, ieee_is_nan(deck%k5))
      lmt = laminate_from_layup(lam, deck%angles, deck%h, scene%k4, scene%k5)
      scene%couplings = laminate_couplings(lmt)
      scene%h = deck%h
      scene%impactor_mass = deck%mass
      scene%plate_mass = deck%rho*deck%h*deck%a*deck%b
      scene%energy = 0.5_dp*deck%mass*deck%velocity**2
   end subroutine model_laminate

   !> Domain. A mirror image about the centre line x = 0 maps the plate onto
   !> itself (the plate is centred, all its edges are alike) and maps the
   !> fields as u -> -u, psi_x -> -psi_x, v, w, psi_y -> themselves, so that
   !> eps_x, eps_y, kappa_x, kappa_y, gamma_yz keep their sign and gamma_xy,
   !> kappa_xy, gamma_xz change it. The laminate law is unchanged by the mirror
   !> image only if it couples no sign-keeping resultant with a sign-changing
   !> strain:
   !>    A16 = A26 = 0,  B16 = B26 = 0,  D16 = D26 = 0,  Abar45 = 0;
   !> B11, B12, B22, B66 (an unsymmetric cross-ply) are allowed. The mirror
   !> image about y = 0 needs exactly the same terms to vanish, so a laminate
   !> allows both mirror lines or neither; the impact point decides which lines
   !> run through it. The von Karman terms and the inertias (R = 0 here) keep
   !> the symmetry. Hence, with 'auto':
   !>  - quarter: the impact point at the centre (x0 = y0 = 0) and the
   !>    laminate mirror-symmetric;
   !>  - half: the laminate mirror-symmetric and the impact point on one
   !>    centre line only: about y = 0 if y0 = 0, about x = 0 if x0 = 0;
   !>  - full: otherwise.
   !> With 'auto', &mesh nx, ny are the quarter plate's counts, doubled along
   !> each direction in which the chosen domain spans both sides of a centre
   !> line, so the choice keeps the element size (src/model/mesh.f90).
   !> "Zero" means below coupling_tol relative to the matching diagonal terms
   !> (rounding of the ply sums). D16 and D26 may instead be accepted as zero
   !> by the deck (&mesh average_bend_twist = .true.): the paper's averaging
   !> argument (section 3.1), the centre response of the layup being the mean
   !> of those of the layup and its mirror image, whose D16, D26 have the
   !> other sign. A forced 'quarter', 'half' or 'strip' (&mesh domain) implies
   !> that acceptance; A16, A26, B16, B26 and Abar45 are never averaged away.
   !> The averaging applies only on a reduced domain: a full plate keeps its
   !> D16, D26. &laminate bend_twist = 'drop' sets D16 = D26 = 0 everywhere
   !> (so 'auto' may pick a reduced domain), 'keep' never (so 'auto' picks a
   !> reduced domain only if they vanish; a forced one is refused by the deck).
   !>
   !> The couplings that a mirror image reverses (as above), each
   !> relative to its diagonal terms, in the order of coupling_names.
   pure function laminate_couplings(lmt) result(c)
      type(laminate_t), intent(in) :: lmt   !< the laminate
      real(dp) :: c(ncouplings)
      c(1) = abs(lmt%d(1,3))/lmt%d(1,1)
      c(2) = abs(lmt%d(2,3))/lmt%d(2,2)
      c(3) = abs(lmt%a(1,3))/lmt%a(1,1)
      c(4) = abs(lmt%a(2,3))/lmt%a(2,2)
      c(5) = abs(lmt%b(1,3))/sqrt(lmt%a(1,1)*lmt%d(1,1))
      c(6) = abs(lmt%b(2,3))/sqrt(lmt%a(2,2)*lmt%d(2,2))
      c(7) = abs(lmt%as(1,2))/sqrt(lmt%as(1,1)*lmt%as(2,2))
   end function laminate_couplings

   !> The modelled domain (above laminate_couplings): 'auto' picks the smallest the
   !> scene allows; a forced domain is checked against the laminate. Sets
   !> scene%domain, scene%averaged and scene%domain_reason. A laminate that
   !> forbids a forced reduced domain is an error naming the deck, &mesh
   !> and domain.
   subroutine choose_domain(deck, scene, stat, errmsg)
      type(deck_t), intent(in) :: deck           !< the validated deck
      type(scene_t), intent(inout) :: scene      !< couplings in; domain, averaged, reason out
      integer, intent(out) :: stat               !< 0 on success
      character(len=*), intent(inout) :: errmsg  !< reason on failure
      logical :: bend_twist_zero, others_zero, mirror, accept_average
      integer :: worst

      stat = 0
      bend_twist_zero = all(scene%couplings(:n_bend_twist) <= coupling_tol)
      others_zero = all(scene%couplings(n_bend_twist+1:) <= coupling_tol)
      worst = n_bend_twist + maxloc(scene%couplings(n_bend_twist+1:), dim=1)
      accept_average = (deck%average_bend_twist .or. deck%bend_twist == 'drop') .and. deck%bend_twist /= 'keep'

      select case (deck%domain)
      case ('auto')
         mirror = others_zero .and. (bend_twist_zero .or. accept_average)
         if (.not. mirror) then
            scene%domain = 'full'
            if (.not. others_zero) then
               scene%domain_reason = 'full: the laminate has ' // coupling_text(worst) &
                  // ', which no mirror image keeps'
            else
               scene%domain_reason = 'full: the laminate has ' // coupling_text(1) // ' and ' &
                  // coupling_text(2) // ', which break both mirror symmetries (&mesh average_bend_twist' &
                  // ' = .true. accepts the paper''s averaging, section 3.1, and a smaller domain)'
            end if
         else if (deck%x0 == 0.0_dp .and. deck%y0 == 0.0_dp) then
            scene%domain = 'quarter'
            scene%domain_reason = 'quarter: the impact point is the centre, the edges are alike and the ' &
               // 'laminate is mirror-symmetric about x = 0 and y = 0'
         else if (deck%y0 == 0.0_dp) then
            scene%domain = 'half'
            scene%domain_reason = 'half, y >= 0 (symmetric about y = 0): the impact point is on y = 0 but ' &
               // 'off x = 0, and the laminate is mirror-symmetric'
         else if (deck%x0 == 0.0_dp) then
            scene%domain = 'half'
            scene%domain_reason = 'half, x >= 0 (symmetric about x = 0): the impact point is on x = 0 but ' &
               // 'off y = 0, and the laminate is mirror-symmetric'
         else
            scene%domain = 'full'
            scene%domain_reason = 'full: the impact point is on neither centre line'
         end if
         if (mirror .and. .not. bend_twist_zero .and. scene%domain /= 'full') &
            scene%domain_reason = trim(scene%domain_reason) // ' once ' // coupling_text(1) // ' and ' &
               // coupling_text(2) // ' are set to 0 (the paper''s averaging, section 3.1, accepted by the deck)'
         if (scene%domain /= 'quarter') scene%domain_reason = trim(scene%domain_reason) &
            // '; nx, ny are the quarter''s counts, doubled across each centre line the domain spans'
      case ('full')
         scene%domain = 'full'
         scene%domain_reason = 'full: forced by the deck (&mesh domain)'
      case default            ! 'quarter', 'half', 'strip': forced, the impact point checked by validate_deck
         if (.not. others_zero) then
            stat = 1
            errmsg = trim(deck%source) // ": &mesh: domain = '" // trim(deck%domain) // "': the laminate has " &
               // coupling_text(worst) // ", which no mirror image keeps: use domain = 'full' or 'auto'"
            return
         end if
         scene%domain = deck%domain
         scene%domain_reason = trim(deck%domain) // ': forced by the deck (&mesh domain)'
         if (.not. bend_twist_zero) scene%domain_reason = trim(scene%domain_reason) // '; ' &
            // coupling_text(1) // ' and ' // coupling_text(2) // ' set to 0: the paper''s averaging ' &
            // '(section 3.1), which forcing a reduced domain accepts'
      end select
      if (scene%domain == 'half' .and. deck%domain /= 'auto') then
         if (deck%y0 == 0.0_dp) then
            scene%domain_reason = trim(scene%domain_reason) // ' (y >= 0, symmetric about y = 0)'
         else
            scene%domain_reason = trim(scene%domain_reason) // ' (x >= 0, symmetric about x = 0)'
         end if
      end if
      scene%averaged = (scene%domain /= 'full' .and. .not. bend_twist_zero) .or. deck%bend_twist == 'drop'
      if (deck%bend_twist == 'drop' .and. .not. bend_twist_zero) scene%domain_reason = trim(scene%domain_reason) &
         // '; D16 = D26 = 0 everywhere (&laminate bend_twist = ''drop'')'

   contains

      !> 'name = value' of coupling i.
      function coupling_text(i) result(text)
         integer, intent(in) :: i   !< coupling index, coupling_names order
         character(len=:), allocatable :: text
         character(len=16) :: v
         write (v, '(es10.3)') scene%couplings(i)
         text = trim(coupling_names(i)) // ' = ' // trim(adjustl(v))
      end function coupling_text

   end subroutine choose_domain

   !> Static estimate (energy balance of a quasi-static impact, the impactor's
   !> energy shared by the plate's bending spring and the Hertz contact):
   !>    1/2 m v^2 = F^2/(2 K) + (2/5) F^(5/3) / k^(2/3)
   !> gives the peak force F, the deflection w = F/K and the indentation
   !> alpha = (F/k)^(2/3) (loading law, eq. 11); K is the plate's static
   !> stiffness at the impact point, 1/w of the linear model K_L under a unit
   !> force there (impact_driver: point_stiffness), which includes the shear
   !> deflection of this mesh. Free edges have no static stiffness: their K is
   !> that of the same plate simply supported, which overstates the deflection
   !> (the plate's inertia, not its edges, holds a free plate during the
   !> contact). The estimate ignores the plate's inertia; it is best for an
   !> impactor much heavier than the plate (the mass ratio is reported) and
   !> otherwise overstates w (docs/validation/model_choice.md measures by how
   !> much).
   !>
   !> The energy balance of a quasi-static impact (as above):
   !> 1/2 m v^2 = F^2/(2K) + (2/5) F^(5/3)/k^(2/3), solved for F by
   !> bisection (the right side grows with F); w = F/K, alpha = (F/k)^(2/3).
   pure subroutine energy_balance(energy, stiffness, k_contact, force, deflection, indentation)
      real(dp), intent(in) :: energy        !< impactor energy 1/2 m v^2 (J)
      real(dp), intent(in) :: stiffness     !< plate stiffness K at the impact point (N/m)
      real(dp), intent(in) :: k_contact     !< contact stiffness k of F = k alpha^1.5 (N/m^1.5)
      real(dp), intent(out) :: force        !< peak force F (N)
      real(dp), intent(out) :: deflection   !< plate deflection F/K (m)
      real(dp), intent(out) :: indentation  !< indentation (F/k)^(2/3) (m)
      real(dp) :: lo, hi, mid
      integer :: it

      ! either term alone taking all the energy bounds F from above
      lo = 0.0_dp
      hi = min(sqrt(2.0_dp*stiffness*energy), (2.5_dp*energy*k_contact**(2.0_dp/3.0_dp))**0.6_dp)
      bisection: do it = 1, max_bisection
         mid = 0.5_dp*(lo + hi)
         if (mid <= lo .or. mid >= hi) exit bisection
         if (stored(mid) > energy) then
            hi = mid
         else
            lo = mid
         end if
      end do bisection
      force = 0.5_dp*(lo + hi)
      deflection = force/stiffness
      indentation = (force/k_contact)**(2.0_dp/3.0_dp)

   contains

      !> Energy stored in the two springs at force f (J).
      pure function stored(f) result(e)
         real(dp), intent(in) :: f   !< contact force (N)
         real(dp) :: e
         e = 0.5_dp*f**2/stiffness + 0.4_dp*f**(5.0_dp/3.0_dp)/k_contact**(2.0_dp/3.0_dp)
      end function stored

   end subroutine energy_balance

   !> Theory. The static estimate of the deflection w at the impact point (an
   !> energy balance, below) is compared with the thickness h: the von Karman
   !> terms stiffen a plate whose edges hold it in its plane by a fraction of
   !> about 0.49 (w/h)^2 of its bending stiffness (clamped circular plate under
   !> a uniform load, immovable edges: Timoshenko & Woinowsky-Krieger, Theory
   !> of Plates and Shells, section 97); above w/h = wh_nonlinear = 0.2 that is
   !> 2 % or more, more than the paper's 6 x 9 mesh error, so 'auto' chooses
   !> the nonlinear theory there and the linear one below (measured:
   !> docs/validation/model_choice.md). After a
   !> linear run the largest bending deflection met is compared with the same
   !> threshold.
   !>
   !> The theory: the deck's, or with 'auto' the estimate's (as above):
   !> nonlinear when w/h > wh_nonlinear.
   pure subroutine choose_theory(requested, w_over_h, theory, reason)
      character(len=*), intent(in) :: requested     !< &analysis theory: 'linear', 'nonlinear' or 'auto'
      real(dp), intent(in) :: w_over_h              !< estimated deflection / thickness (-)
      character(len=*), intent(out) :: theory       !< 'linear' or 'nonlinear'
      character(len=*), intent(out) :: reason       !< why
      character(len=12) :: v, t
      logical :: needed

      write (v, '(f8.3)') w_over_h
      write (t, '(f5.2)') wh_nonlinear
      needed = w_over_h > wh_nonlinear
      if (requested == 'auto') then
         theory = merge('nonlinear', 'linear   ', needed)
         if (needed) then
            reason = trim(theory) // " (auto): estimated w/h = " // trim(adjustl(v)) // ' > ' // trim(adjustl(t)) &
               // ', the von Karman terms matter'
         else
            reason = trim(theory) // " (auto): estimated w/h = " // trim(adjustl(v)) // ' <= ' // trim(adjustl(t)) &
               // ', the von Karman terms are negligible'
         end if
      else
         theory = requested
         reason = trim(theory) // ' (&analysis theory); estimated w/h = ' // trim(adjustl(v)) // ' against ' &
            // trim(adjustl(t)) // merge(': the von Karman terms matter    ', ': the von Karman terms negligible', &
            needed)
      end if
   end subroutine choose_theory

   !> The storage of the matrices: the deck's, or with 'auto' band below
   !> sparse_crossover equations and sparse from there on, band for the
   !> modal analysis (src/linalg/storage_choice.f90 says why).
   subroutine choose_storage(requested, neq, band_only, scene)
      character(len=*), intent(in) :: requested   !< &analysis storage
      integer, intent(in) :: neq                  !< number of equations of the model
      logical, intent(in) :: band_only            !< the analysis needs band storage (kind = 'modes')
      type(scene_t), intent(inout) :: scene       !< storage and storage_reason set
      character(len=12) :: n, limit

      write (n, '(i0)') neq
      write (limit, '(i0)') sparse_crossover
      scene%storage = resolve_storage(requested, neq, band_only)
      if (requested /= 'auto') then
         scene%storage_reason = trim(scene%storage) // ' (&analysis storage); ' // trim(n) // ' equations'
      else if (band_only) then
         scene%storage_reason = "band (auto): the modal analysis needs band storage (LAPACK's dsbgvx)"
      else if (scene%storage == 'band') then
         scene%storage_reason = 'band (auto): ' // trim(n) // ' equations < ' // trim(limit) &
            // ', where band is as fast as sparse (LAPACK)'
      else
         scene%storage_reason = 'sparse (auto): ' // trim(n) // ' equations >= ' // trim(limit) &
            // ', where sparse is faster and smaller than band (CHOLMOD)'
      end if
   end subroutine choose_storage

   !> After a linear run: true, with a message, when the largest deflection
   !> met needed the nonlinear theory (w/h > wh_nonlinear).
   pure subroutine theory_warning(scene, w_max, warn, text)
      type(scene_t), intent(in) :: scene        !< the scene (theory and thickness)
      real(dp), intent(in) :: w_max             !< largest bending deflection of the run (m)
      logical, intent(out) :: warn              !< the linear theory was not enough
      character(len=*), intent(out) :: text     !< the warning
      character(len=12) :: v, t
      warn = scene%theory == 'linear' .and. abs(w_max) > wh_nonlinear*scene%h
      text = ''
      if (.not. warn) return
      write (v, '(f8.3)') abs(w_max)/scene%h
      write (t, '(f5.2)') wh_nonlinear
      text = 'the linear run reached w/h = ' // trim(adjustl(v)) // ' > ' // trim(adjustl(t)) &
         // ": its deflection needed the nonlinear theory (&analysis theory = 'nonlinear' or 'auto')"
   end subroutine theory_warning

   !> Contact radius: Hertz, a = sqrt(R alpha), R the nose radius, alpha at the
   !> estimated peak force. With &contact load = 'hertz' (the default) the
   !> force is spread over that disc (src/model/contact_load.f90), whatever the
   !> element size. With the paper's point force (load = 'point') it is
   !> applied at the impact node, which is consistent only while a is much
   !> smaller than the element there: an element smaller than the contact's
   !> diameter (a/element > max_radius_ratio = 0.5) resolves a point load that
   !> the contact does not apply (under a point force the Mindlin plate's
   !> deflection grows without bound, logarithmically, as the mesh is refined
   !> there, and the slopes at the point steepen, which slows and can stop the
   !> convergence of the eq. (19) iteration: docs/validation/model_choice.md,
   !> section 5); the report warns.
   !>
   !> The scene report, before the run: every choice with its reason and the
   !> distance from each simplification.
   subroutine write_scene_report(scene, unit)
      type(scene_t), intent(in) :: scene   !< the assessed scene
      integer, intent(in) :: unit          !< open formatted unit
      character(len=*), parameter :: lead = 'scene: '

      write (unit, '(a)') lead // 'how far the scene is from each simplification, and the choices made'
      if (scene%k_whitney) then
         write (unit, '(a,f7.4,a,f7.4,a)') lead // 'shear correction  k4 = ', scene%k4, ', k5 = ', scene%k5, &
            " (Whitney's method from the layup where the deck gives none; these are k, Abar44 = k4^2 int Q44)"
      else
         write (unit, '(a,f7.4,a,f7.4,a)') lead // 'shear correction  k4 = ', scene%k4, ', k5 = ', scene%k5, &
            ' (the deck)'
      end if
      write (unit, '(a)') lead // 'bend-twist        ' // couplings_text(1, n_bend_twist) &
         // " (the paper's averaging, section 3.1, may set them to 0)"
      write (unit, '(a)') lead // 'other couplings   ' // couplings_text(n_bend_twist + 1, ncouplings) &
         // ' (never averaged)'
      write (unit, '(a)') lead // 'domain            ' // trim(scene%domain_reason)
      write (unit, '(a,es10.3,a)') lead // 'static stiffness  K = ', scene%stiffness, ' N/m at the impact point, ' &
         // trim(scene%stiffness_note)
      write (unit, '(a,es10.3,a,es10.3,a,f7.3,a)') lead // 'energy balance    F = ', scene%force, ' N, w = ', &
         scene%deflection, ' m, w/h = ', scene%deflection/scene%h, &
         ' (1/2 m v^2 = F^2/2K + 2/5 F^5/3 / k^2/3, no plate inertia)'
      write (unit, '(a)') lead // 'theory            ' // trim(scene%theory_reason)
      if (len_trim(scene%storage_reason) > 0) write (unit, '(a)') lead // 'storage           ' &
         // trim(scene%storage_reason)
      write (unit, '(a,es10.3,a,es10.3,a,es10.3,a,es10.3,a,f7.3)') lead // 'contact radius    a = ', &
         scene%contact_radius, ' m (Hertz, alpha = ', scene%indentation, ' m); element at the impact point ', &
         scene%element_size(1), ' x ', scene%element_size(2), ' m; a/element = ', &
         scene%contact_radius/minval(scene%element_size)
      if (scene%point_load .and. scene%contact_radius > max_radius_ratio*minval(scene%element_size)) &
         write (unit, '(a,f4.2,a)') &
         lead // 'warning: the element at the impact point is smaller than the contact''s diameter (a/element > ', &
         max_radius_ratio, '): the point force is resolved more finely than the contact applies it, and the' &
         // ' eq. (19) iteration may converge slowly or not at all; use a coarser element there (grading, nx, ny)'
      write (unit, '(a,es10.3,a,es10.3,a,f8.3)') lead // 'mass ratio        impactor/plate = ', &
         scene%impactor_mass, ' kg / ', scene%plate_mass, ' kg = ', scene%impactor_mass/scene%plate_mass

   contains

      !> 'name = value, ...' of couplings first..last.
      function couplings_text(first, last) result(text)
         integer, intent(in) :: first, last   !< coupling indices, coupling_names order
         character(len=:), allocatable :: text
         character(len=12) :: v
         integer :: j
         text = ''
         do j = first, last
            write (v, '(es9.2)') scene%couplings(j)
            if (j > first) text = text // ', '
            text = text // trim(coupling_names(j)) // ' = ' // trim(adjustl(v))
         end do
      end function couplings_text

   end subroutine write_scene_report

   !> The plate's static stiffness at the impact point, K = 1/w under a unit
   !> force on the whole plate (above energy_balance): K_L of the model's mesh,
   !> factored here once more (not counted among the run's factorisations);
   !> free edges are replaced by simply supported ones. When the edges the
   !> estimate holds are the model's own (clamped; simply supported and
   !> immovable), K_L is a copy of the model's assembled [K_L], else it is
   !> assembled anew. (An iterative solve preconditioned by the run's factor
   !> of K_L + 4/dt^2 M would spare this factorization, but it needs some
   !> 100 solves for K to 1e-7, 60 for 1 %, the cost of 3-4
   !> factorizations: docs/PERFORMANCE.md, "The set-up's second
   !> factorization".)
   subroutine point_stiffness(msh, lmt, geo, stiff, edges, scene, stat, errmsg)
      type(mesh_t), intent(in) :: msh                    !< the model's mesh and freedoms
      type(laminate_t), intent(in) :: lmt                !< the model's laminate
      type(element_geometry_t), intent(in) :: geo(:)     !< per-element geometry
      type(global_matrix_t), intent(in) :: stiff         !< the model's [K_L], assembled in its storage
      character(len=*), intent(in) :: edges              !< &boundary edges
      type(scene_t), intent(inout) :: scene              !< its storage; stiffness and stiffness_note set
      integer, intent(out) :: stat                       !< 0 on success
      character(len=*), intent(inout) :: errmsg          !< reason on failure
      type(mesh_t) :: m
      type(global_matrix_t) :: k
      real(dp) :: ke(nfe, nfe)
      real(dp), allocatable :: rhs(:)
      integer :: e, bad_eq, ieq

      m = msh
      if (edges == 'free') then
         call apply_boundary(m, 'simply_supported', 'immovable', stat, errmsg)
         if (stat /= 0) return
         scene%stiffness_note = 'free edges replaced by simply supported ones (a free plate has none)'
      else if (edges == 'simply_supported') then
         ! movable edges leave the in-plane rigid-body modes to the mass matrix,
         ! which K_L alone lacks: the estimate holds them (immovable edges)
         call apply_boundary(m, 'simply_supported', 'immovable', stat, errmsg)
         if (stat /= 0) return
         scene%stiffness_note = 'simply supported edges, in-plane held, K_L of this mesh (bending and shear)'
      else
         scene%stiffness_note = trim(edges) // ' edges, K_L of this mesh (bending and shear)'
      end if
      if (all(m%eq == msh%eq)) then
         call global_copy(k, stiff)                 ! the model's own freedoms: its K_L as assembled
      else
         call global_init(k, scene%storage, m%neq, m%elem_eq, stat, errmsg)
         if (stat /= 0) return
         call global_zero(k)
         elements: do e = 1, m%nelem
            call element_stiffness(lmt, geo(e), ke)
            call global_assemble(k, ke, m%elem_eq(:, e))
         end do elements
      end if
      call global_factor(k, stat, errmsg, bad_eq)
      if (stat /= 0) then
         errmsg = 'scene: static stiffness: ' // trim(errmsg)
         call global_release(k)
         return
      end if
      ieq = m%eq(3, m%impact_node)
      allocate (rhs(m%neq))
      rhs = 0.0_dp
      rhs(ieq) = 1.0_dp/msh%sym_factor            ! the share of the force the domain carries
      call global_solve(k, rhs, stat, errmsg)
      call global_release(k)          ! before the run's own factorization (sparse: C memory)
      if (stat /= 0) return
      scene%stiffness = 1.0_dp/rhs(ieq)
   end subroutine point_stiffness

   !> Sides along x and y of the element at the impact point (m).
   pure function impact_element_size(msh) result(size_xy)
      type(mesh_t), intent(in) :: msh   !< the mesh
      real(dp) :: size_xy(2)
      integer :: nodes(size(msh%conn, 1))
      nodes = msh%conn(:, msh%impact_elem)
      size_xy = maxval(msh%coords(:, nodes), dim=2) - minval(msh%coords(:, nodes), dim=2)
   end function impact_element_size

   !> Deflection at the impact point that bends the plate (m): w there, less
   !> for free edges the rigid-body plane w = c1 + c2 x + c3 y fitted by least
   !> squares (LAPACK dgels) to w at the nodes of the plate's edges (the
   !> x-term is absent on a domain symmetric about x = 0, the y-term about
   !> y = 0). Supported edges hold w, so there the plane is zero.
   subroutine bending_deflection(msh, edges, d, w, stat, errmsg)
      type(mesh_t), intent(in) :: msh             !< the mesh and freedoms
      character(len=*), intent(in) :: edges       !< &boundary edges
      real(dp), intent(in) :: d(:)                !< global displacements
      real(dp), intent(out) :: w                  !< bending deflection at the impact point (m)
      integer, intent(out) :: stat                !< 0 on success
      character(len=*), intent(inout) :: errmsg   !< reason on failure
      real(dp), allocatable :: a(:,:), b(:), work(:)
      real(dp) :: basis(max_plane_terms), work_size(1)
      integer :: i, j, n, np, nt, ngx, ngy, info, ieq
      logical :: on_edge

      stat = 0
      w = d(msh%eq(3, msh%impact_node))
      if (edges /= 'free') return
      ngx = 2*msh%nx + 1;  ngy = 2*msh%ny + 1
      nt = 1 + merge(0, 1, msh%sym_x) + merge(0, 1, msh%sym_y)
      allocate (a(2*(ngx + ngy), nt), b(2*(ngx + ngy)))
      np = 0
      grid_nodes: do j = 0, ngy - 1
         do i = 0, ngx - 1
            on_edge = i == ngx - 1 .or. (i == 0 .and. .not. msh%sym_x) &
               .or. (j == ngy - 1 .and. msh%domain /= 'strip') .or. (j == 0 .and. .not. msh%sym_y)
            if (.not. on_edge) cycle
            n = msh%grid(i, j)
            ieq = msh%eq(3, n)
            np = np + 1
            basis = plane_basis(msh%coords(:, n))
            a(np, :) = basis(:nt)
            b(np) = 0.0_dp
            if (ieq > 0) b(np) = d(ieq)
         end do
      end do grid_nodes
      call dgels('N', np, nt, 1, a, size(a, 1), b, size(b), work_size, -1, info)
      if (info == 0) then
         allocate (work(max(1, nint(work_size(1)))))
         call dgels('N', np, nt, 1, a, size(a, 1), b, size(b), work, size(work), info)
      end if
      if (info /= 0) then
         stat = 1
         write (errmsg, '(a,i0)') 'scene: rigid-body plane of the free edges: LAPACK dgels info = ', info
         return
      end if
      basis = plane_basis(msh%coords(:, msh%impact_node))
      w = w - dot_product(basis(:nt), b(:nt))

   contains

      !> 1, then x unless x = 0 is a symmetry line, then y unless y = 0 is.
      pure function plane_basis(xy) result(f)
         real(dp), intent(in) :: xy(2)   !< point (x, y) from the plate centre (m)
         real(dp) :: f(max_plane_terms)
         integer :: k
         f = 0.0_dp
         f(1) = 1.0_dp
         k = 1
         if (.not. msh%sym_x) then
            k = k + 1
            f(k) = xy(1)
         end if
         if (.not. msh%sym_y) then
            k = k + 1
            f(k) = xy(2)
         end if
      end function plane_basis

   end subroutine bending_deflection

end module scene_model
