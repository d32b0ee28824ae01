!> The plate's ply damage: the state of every ply at every 3 x 3 Gauss
!> point (src/strength/ply_damage.f90 for one ply at one point), updated
!> once per accepted time step from the converged displacements, and what
!> it costs the plate. A, B, D of eq. (6) and the shear stiffness Abar are
!> integrated again from the damaged plies, Q(d) in place of eq. (3)'s Q;
!> the left-hand matrix K_L + 4/dt^2 M of eq. (19) stays the undamaged one
!> and the stiffness lost goes to its right-hand side beside K_N(D) D:
!>   (K_L + 4/dt^2 M) D^{n+1} = F + M b - K_N(D^n) D^n - K_D(D^n) D^n,
!> K_D D the internal force of dA, dB, dD, dAbar (negative: the plate is
!> softer). Damage is explicit in time: step n+1 is solved with the damage
!> of step n. More: docs/STRENGTH.md, "Progressive ply damage".
module plate_damage
   use kinds, only: dp, pi
   use materials, only: lamina_t, lamina_qbar_shear
   use failure_criteria, only: strength_t
   use ply_damage, only: damage_card_t, ply_damage_step, damaged_q, ndmode, dmode_names
   use shape_functions, only: nen
   use mesh, only: nfe
   use plate_model, only: model_t, gather_element, scatter_add_element
   use element_matrices, only: point_strains, shear_strains, von_karman
   use deck_schema, only: deck_t, strength_given, is_given
   implicit none
   private
   public :: plate_damage_t, damage_init, damage_update, damage_force, damage_counts, damage_wanted

   !> Gauss points per element (the 3 x 3 of the membrane and bending terms).
   integer, parameter :: ngp = 9

   !> The damage of a run.
   type :: plate_damage_t
      logical :: on = .false.                    !< the model is in use
      logical :: hit_any = .false.               !< some ply somewhere is damaged
      character(len=:), allocatable :: why       !< which model and why (summary damage_model)
      type(damage_card_t) :: card                !< the ply's material
      logical :: nonlinear = .true.              !< von Karman strains
      integer :: nply = 0, nelem = 0
      real(dp), allocatable :: angle(:), zm(:), dz(:), dz2(:), dz3(:)   !< (nply) angle (deg), mid z, int dz, z dz, z^2 dz
      real(dp), allocatable :: d(:,:,:,:), dv(:,:,:,:)   !< (ndmode, nply, ngp, nelem) damage and its viscous shadow
      real(dp), allocatable :: lc(:,:)           !< (ngp, nelem) characteristic length, sqrt(w det J) (m)
      real(dp), allocatable :: dc(:,:,:,:)       !< (6, 6, ngp, nelem) [dA dB; dB dD] of the damaged plies
      real(dp), allocatable :: das(:,:,:)        !< (2, 2, nelem) dAbar of the element
      logical, allocatable :: hit(:)             !< (nelem) a ply of the element is damaged
      real(dp) :: dissipated = 0.0_dp            !< energy dissipated, whole plate (J)
      real(dp) :: u_lost = 0.0_dp                !< damage_energy at the last update's displacements (J)
      integer :: snapback_points = 0             !< ply points whose strengths the snap-back guard reduced
   end type plate_damage_t

contains

   !> The model of &damage model: 'hashin' on, 'none' off, 'auto' on when
   !> the deck gives the six ply strengths and the four ply fracture energies
   !> (damage can then start wherever a ply's Hashin index reaches 1, and
   !> nothing changes before), else off. eta: &damage viscosity (s).
   subroutine damage_init(deck, model, word, eta, dmg, stat, errmsg)
      type(deck_t), intent(in) :: deck          !< the effective deck
      type(model_t), intent(in) :: model        !< the model
      character(len=*), intent(in) :: word      !< &damage model
      real(dp), intent(in) :: eta               !< &damage viscosity (s)
      type(plate_damage_t), intent(out) :: dmg  !< the state
      integer, intent(out) :: stat              !< 0, or 1 when 'hashin' lacks its data
      character(len=*), intent(inout) :: errmsg !< why
      logical :: data
      integer :: k
      stat = 0
      data = damage_data(deck)
      select case (word)
      case ('none')
         dmg%why = 'none (&damage model = ''none'')'
         return
      case ('hashin')
         if (.not. data) then
            stat = 1
            errmsg = '&damage model = ''hashin'' needs &strength xt, xc, yt, yc, s12, s23 and gft, gfc, gmt, gmc'
            return
         end if
         dmg%why = 'hashin (&damage model = ''hashin'')'
      case default
         if (.not. data) then
            dmg%why = 'none (auto: &strength gives no ply strengths and fracture energies)'
            return
         end if
         dmg%why = 'hashin (auto: &strength gives the ply strengths and fracture energies)'
      end select
      dmg%on = .true.
      dmg%nonlinear = model%nonlinear
      dmg%card = damage_card_t(lamina_t(deck%e1, deck%e2, deck%g12, deck%g13, deck%g23, deck%nu12, deck%rho), &
         strength_t(deck%xt, deck%xc, deck%yt, deck%yc, deck%s12, deck%s23), &
         [deck%gft, deck%gfc, deck%gmt, deck%gmc], 0.0_dp, eta)
      dmg%nply = size(deck%angles);  dmg%nelem = model%msh%nelem
      allocate (dmg%angle(dmg%nply), dmg%zm(dmg%nply), dmg%dz(dmg%nply), dmg%dz2(dmg%nply), dmg%dz3(dmg%nply))
      dmg%angle = deck%angles
      do k = 1, dmg%nply
         associate (z0 => -0.5_dp*deck%h + deck%h*real(k - 1, dp)/real(dmg%nply, dp), &
                    z1 => -0.5_dp*deck%h + deck%h*real(k, dp)/real(dmg%nply, dp))
            dmg%zm(k) = 0.5_dp*(z0 + z1)
            dmg%dz(k) = z1 - z0;  dmg%dz2(k) = (z1**2 - z0**2)/2.0_dp;  dmg%dz3(k) = (z1**3 - z0**3)/3.0_dp
         end associate
      end do
      allocate (dmg%d(ndmode, dmg%nply, ngp, dmg%nelem), dmg%dv(ndmode, dmg%nply, ngp, dmg%nelem), &
                dmg%lc(ngp, dmg%nelem), dmg%dc(6, 6, ngp, dmg%nelem), dmg%das(2, 2, dmg%nelem), dmg%hit(dmg%nelem))
      dmg%d = 0.0_dp;  dmg%dv = 0.0_dp;  dmg%dc = 0.0_dp;  dmg%das = 0.0_dp;  dmg%hit = .false.
      do k = 1, dmg%nelem
         dmg%lc(:, k) = sqrt(model%geo(k)%wj3)
      end do
   end subroutine damage_init

   !> The deck gives the six ply strengths and the four ply fracture energies.
   pure logical function damage_data(deck)
      type(deck_t), intent(in) :: deck          !< the effective deck
      damage_data = strength_given(deck) .and. is_given(deck, 'strength', 'gft') .and. is_given(deck, 'strength', 'gfc') &
                    .and. is_given(deck, 'strength', 'gmt') .and. is_given(deck, 'strength', 'gmc')
   end function damage_data

   !> The plies of a run with this deck damage (damage_init, without its
   !> state): the history's column of the energy dissipated.
   pure logical function damage_wanted(deck)
      type(deck_t), intent(in) :: deck          !< the effective deck
      damage_wanted = deck%damage_model == 'hashin' .or. (deck%damage_model /= 'none' .and. damage_data(deck))
   end function damage_wanted

   !> The damage after an accepted step of length dt, at the displacements d:
   !> every ply at its mid-thickness at every Gauss point (ply_damage_step),
   !> and the stiffness lost of the elements hit. The energy dissipated is
   !> the plate's strain energy the new damage takes at d (damage_energy
   !> before less after): the ply's own count at its mid-thickness,
   !> through the thickness and in transverse shear, so that the energy
   !> balance closes with it.
   subroutine damage_update(dmg, model, d, dt)
      type(plate_damage_t), intent(inout) :: dmg   !< the state
      type(model_t), intent(in) :: model           !< the model
      real(dp), intent(in) :: d(:)                 !< displacements {D} of the accepted step
      real(dp), intent(in) :: dt                   !< the step (s)
      real(dp) :: de(nfe), e0(3), kap(3), wx, wy, eps(3), diss, u_before, dv_old(ndmode, dmg%nply)
      logical :: snap(ndmode), changed
      integer :: el, g, k
      if (.not. dmg%on) return
      u_before = damage_energy(dmg, model, d)
      elements: do el = 1, dmg%nelem
         call gather_element(model%msh%elem_eq(:, el), d, de)
         changed = .false.
         points: do g = 1, ngp
            call point_strains(model%geo(el)%dx3(:, :, g), de, e0, kap, wx, wy)
            if (dmg%nonlinear) e0 = e0 + von_karman(wx, wy)
            dv_old = dmg%dv(:, :, g, el)
            plies: do k = 1, dmg%nply
               eps = to_material(dmg%angle(k), e0 + dmg%zm(k)*kap)
               call ply_damage_step(dmg%card, eps, dmg%lc(g, el), dt, dmg%d(:, k, g, el), dmg%dv(:, k, g, el), &
                                    snap, diss)
               if (any(snap)) dmg%snapback_points = dmg%snapback_points + 1
            end do plies
            if (any(dmg%dv(:, :, g, el) /= dv_old)) then
               changed = .true.
               call point_stiffness_lost(dmg, g, el, e0, kap)
            end if
         end do points
         if (changed) then
            dmg%hit(el) = .true.
            call element_shear_lost(dmg, model, el)
         end if
      end do elements
      dmg%hit_any = any(dmg%hit)
      dmg%u_lost = damage_energy(dmg, model, d)
      dmg%dissipated = dmg%dissipated + u_before - dmg%u_lost
   end subroutine damage_update

   !> [dA dB; dB dD] at point g of element el: the plies' Qbar(d) - Qbar(0),
   !> integrated through the thickness as eq. (6) does, the fibre and matrix
   !> damage each ply's strain at the point selects.
   subroutine point_stiffness_lost(dmg, g, el, e0, kap)
      type(plate_damage_t), intent(inout) :: dmg
      integer, intent(in) :: g, el
      real(dp), intent(in) :: e0(3), kap(3)
      real(dp) :: dq(3,3), t(3,3), eps(3)
      integer :: k
      dmg%dc(:, :, g, el) = 0.0_dp
      do k = 1, dmg%nply
         if (all(dmg%dv(:, k, g, el) == 0.0_dp)) cycle
         eps = to_material(dmg%angle(k), e0 + dmg%zm(k)*kap)
         t = strain_rotation(dmg%angle(k))
         dq = matmul(transpose(t), matmul(damaged_q(dmg%card%lam, dmg%dv(:, k, g, el), eps) &
                                          - damaged_q(dmg%card%lam, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]), t))
         dmg%dc(1:3, 1:3, g, el) = dmg%dc(1:3, 1:3, g, el) + dq*dmg%dz(k)
         dmg%dc(1:3, 4:6, g, el) = dmg%dc(1:3, 4:6, g, el) + dq*dmg%dz2(k)
         dmg%dc(4:6, 4:6, g, el) = dmg%dc(4:6, 4:6, g, el) + dq*dmg%dz3(k)
      end do
      dmg%dc(4:6, 1:3, g, el) = transpose(dmg%dc(1:3, 4:6, g, el))
   end subroutine point_stiffness_lost

   !> dAbar of element el: the laminate's Abar (shear correction included)
   !> times the share of the plies' transverse shear stiffness lost, each
   !> ply's G13, G23 scaled by its shear damage 1 - d_s averaged over the
   !> element's points.
   subroutine element_shear_lost(dmg, model, el)
      type(plate_damage_t), intent(inout) :: dmg
      type(model_t), intent(in) :: model
      integer, intent(in) :: el
      real(dp) :: qs(2,2), lost(2,2), full(2,2), ds
      integer :: k, g
      lost = 0.0_dp;  full = 0.0_dp
      do k = 1, dmg%nply
         qs = lamina_qbar_shear(dmg%card%lam, dmg%angle(k))*dmg%dz(k)
         ds = 0.0_dp
         do g = 1, ngp
            ds = ds + (1.0_dp - product(1.0_dp - dmg%dv(:, k, g, el)))/real(ngp, dp)
         end do
         full = full + qs;  lost = lost + ds*qs
      end do
      where (full /= 0.0_dp)
         dmg%das(:, :, el) = -model%lmt%as*lost/full
      elsewhere
         dmg%das(:, :, el) = 0.0_dp
      end where
   end subroutine element_shear_lost

   !> f = f + K_D(d) d, the internal force of the stiffness lost (above the
   !> module): Bm^T dN + Bb^T dM (+ Bnl^T dN, von Karman) at the Gauss
   !> points, Bs^T dAbar gamma at the shear points, elements hit only.
   subroutine damage_force(dmg, model, d, f)
      type(plate_damage_t), intent(in) :: dmg      !< the state
      type(model_t), intent(in) :: model           !< the model
      real(dp), intent(in) :: d(:)                 !< displacements
      real(dp), intent(inout) :: f(:)              !< force added to
      real(dp) :: de(nfe), fe(nfe), e0(3), kap(3), wx, wy, s(6), gam(2), q(2)
      integer :: el, g, i
      if (.not. dmg%hit_any) return
      elements: do el = 1, dmg%nelem
         if (.not. dmg%hit(el)) cycle elements
         call gather_element(model%msh%elem_eq(:, el), d, de)
         fe = 0.0_dp
         associate (geo => model%geo(el))
            points: do g = 1, ngp
               call point_strains(geo%dx3(:, :, g), de, e0, kap, wx, wy)
               if (dmg%nonlinear) e0 = e0 + von_karman(wx, wy)
               s = geo%wj3(g)*matmul(dmg%dc(:, :, g, el), [e0, kap])     ! wj (dN, dM)
               if (.not. dmg%nonlinear) then
                  wx = 0.0_dp;  wy = 0.0_dp
               end if
               do i = 1, nen
                  associate (px => geo%dx3(1, i, g), py => geo%dx3(2, i, g))
                     fe(5*i-4) = fe(5*i-4) + px*s(1) + py*s(3)
                     fe(5*i-3) = fe(5*i-3) + py*s(2) + px*s(3)
                     fe(5*i-2) = fe(5*i-2) + (wx*px)*s(1) + (wy*py)*s(2) + (wx*py + wy*px)*s(3)
                     fe(5*i-1) = fe(5*i-1) + px*s(4) + py*s(6)
                     fe(5*i)   = fe(5*i)   + py*s(5) + px*s(6)
                  end associate
               end do
            end do points
            shear_points: do g = 1, geo%shear%npoint
               gam = shear_strains(geo%shear%b(:, :, :, g), de)
               q = geo%shear%wj(g)*matmul(dmg%das(:, :, el), gam)
               do i = 1, nen
                  fe(5*i-2) = fe(5*i-2) + dot_product(geo%shear%b(:, 1, i, g), q)
                  fe(5*i-1) = fe(5*i-1) + dot_product(geo%shear%b(:, 2, i, g), q)
                  fe(5*i)   = fe(5*i)   + dot_product(geo%shear%b(:, 3, i, g), q)
               end do
            end do shear_points
         end associate
         call scatter_add_element(model%msh%elem_eq(:, el), fe, f)
      end do elements
   end subroutine damage_force

   !> The change of the plate's strain energy the damage makes at d, whole
   !> plate (J, negative): 1/2 int (eps dC eps) + 1/2 int (gamma dAbar gamma).
   function damage_energy(dmg, model, d) result(u)
      type(plate_damage_t), intent(in) :: dmg      !< the state
      type(model_t), intent(in) :: model           !< the model
      real(dp), intent(in) :: d(:)                 !< displacements
      real(dp) :: u
      real(dp) :: de(nfe), e0(3), kap(3), wx, wy, gam(2), x(6)
      integer :: el, g
      u = 0.0_dp
      if (.not. dmg%hit_any) return
      elements: do el = 1, dmg%nelem
         if (.not. dmg%hit(el)) cycle elements
         call gather_element(model%msh%elem_eq(:, el), d, de)
         associate (geo => model%geo(el))
            do g = 1, ngp
               call point_strains(geo%dx3(:, :, g), de, e0, kap, wx, wy)
               if (dmg%nonlinear) e0 = e0 + von_karman(wx, wy)
               x = [e0, kap]
               u = u + 0.5_dp*geo%wj3(g)*dot_product(x, matmul(dmg%dc(:, :, g, el), x))
            end do
            do g = 1, geo%shear%npoint
               gam = shear_strains(geo%shear%b(:, :, :, g), de)
               u = u + 0.5_dp*geo%shear%wj(g)*dot_product(gam, matmul(dmg%das(:, :, el), gam))
            end do
         end associate
      end do elements
      u = u*model%msh%sym_factor
   end function damage_energy

   !> The ply points (one per ply per Gauss point, the modelled share of
   !> the plate) each mode damaged, and those whose strengths the snap-back
   !> guard reduced, in words (the summary's damaged_ply_points).
   function damage_counts(dmg) result(text)
      type(plate_damage_t), intent(in) :: dmg      !< the state
      character(len=:), allocatable :: text
      character(len=16) :: n
      integer :: m
      text = ''
      do m = 1, ndmode
         write (n, '(i0)') count(dmg%d(m, :, :, :) > 0.0_dp)
         text = text // trim(dmode_names(m)) // ' ' // trim(n) // ', '
      end do
      write (n, '(i0)') dmg%snapback_points
      text = text // 'strengths reduced against snap-back (Maimi 2007) ' // trim(n)
   end function damage_counts

   ! ---------------------------------------------------------------- kernels

   !> Strains (eps_x, eps_y, gamma_xy) into the ply's axes (eps11, eps22,
   !> gamma12), fibres at angle theta from x.
   pure function to_material(theta, e) result(eps)
      real(dp), intent(in) :: theta, e(3)
      real(dp) :: eps(3), t(3,3)
      integer :: i
      t = strain_rotation(theta)
      do i = 1, 3                        ! (not matmul: gfortran 12 warns of its temporary)
         eps(i) = t(i, 1)*e(1) + t(i, 2)*e(2) + t(i, 3)*e(3)
      end do
   end function to_material

   !> The rotation of engineering strains into the ply's axes (Jones 1975,
   !> ch. 2); Qbar = T^T Q T.
   pure function strain_rotation(theta) result(t)
      real(dp), intent(in) :: theta
      real(dp) :: t(3,3), c, s
      c = cos(theta*pi/180.0_dp);  s = sin(theta*pi/180.0_dp)
      t(1, :) = [c*c, s*s, c*s]
      t(2, :) = [s*s, c*c, -c*s]
      t(3, :) = [-2.0_dp*c*s, 2.0_dp*c*s, c*c - s*s]
   end function strain_rotation

end module plate_damage
