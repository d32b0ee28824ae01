!> Where and when damage starts: the ply stresses of the impact run at every Gauss point of every
!> ply (eq. 2-3, src/strength/ply_stress.f90), their failure index
!> (src/strength/failure_criteria.f90), the delamination threshold and index
!> (src/strength/delamination.f90), and what the run records of them: every history step, at the
!> largest contact force and at the end. Only with &strength (the six strengths given); without it
!> the record is inactive. More: docs/STRENGTH.md, "Ply stresses and failure".
module damage_record
   use kinds, only: dp, msg_len
   use deck_schema, only: deck_t, strength_given, is_given
   use materials, only: lamina_t
   use shape_functions, only: nen
   use mesh, only: nfe
   use plate_model, only: model_t, gather_element
   use ply_stress, only: ply_stack_t, ply_stack_init, ply_stresses, point_strain_state, element_second_derivatives, &
      nstate, ngp
   use failure_criteria, only: strength_t, criterion_code, failure_index, failure_indices, mode_names, mode_none, nmode
   use result_files, only: summary_item_t, summary_real, summary_integer, summary_text
   use results_hdf5, only: results_file_t, attr_text, attr_unit
   use hdf5_io, only: h5io_group, h5io_set_attr, h5io_write
   use xdmf_plies, only: ply_maps_t, plies_write, plies_add
   use plate_damage, only: plate_damage_t, damage_counts
   use ply_damage, only: ndmode, dmode_names
   use delamination, only: delamination_t, delamination_open, delamination_force, delamination_point, impact_regime
   implicit none
   private
   public :: damage_t, damage_open, damage_step, damage_peak, damage_close, damage_stresses, damage_points

   !> The damage record of a run (module header).
   type :: damage_t
      logical :: active = .false.                   !< &strength given
      type(strength_t) :: strength                  !< the ply strengths (Pa)
      integer :: criterion = 0                      !< failure_criteria's code
      character(len=:), allocatable :: criterion_name
      type(ply_stack_t) :: stack                    !< the laminate's through-thickness tables
      logical :: nonlinear = .false.                !< von Karman strains
      integer :: nply = 0, npoint = 0               !< plies; Gauss points (9 per element)
      real(dp), allocatable :: d2(:,:,:,:)          !< (3, nen, ngp, nelem) second derivatives of the shape functions (1/m^2)
      real(dp), allocatable :: fi_max(:,:)          !< (nply, npoint) largest index over the run
      integer, allocatable :: mode_max(:,:)         !< (nply, npoint) its mode
      real(dp), allocatable :: onset_time(:,:)      !< (nply, npoint) first time the index reached 1 (s), -1 never
      real(dp) :: smax(5) = 0.0_dp                  !< largest |s11|, |s22|, |t12|, |t23|, |t13| over the run (Pa)
      ! -- failure indices (-), times (s), forces (N), displacements (m, rad)
      ! -- the step just evaluated
      real(dp) :: step_fi = 0.0_dp
      integer :: step_mode = mode_none
      ! -- the run's largest index
      real(dp) :: max_fi = 0.0_dp, max_time = 0.0_dp
      integer :: max_mode = mode_none, max_ply = 0, max_point = 0
      ! -- the onset: the first step with an index >= 1
      real(dp) :: onset = -1.0_dp, onset_fi = 0.0_dp
      integer :: onset_mode = mode_none, onset_ply = 0, onset_point = 0
      ! -- the state at the largest contact force
      real(dp), allocatable :: d_peak(:)
      real(dp) :: peak_force = 0.0_dp, peak_time = 0.0_dp
      integer :: peak_step = 0
      ! -- delamination: thresholds (g2c), regime, Choi & Chang's interfaces (src/strength/delamination.f90)
      type(delamination_t) :: delam
   end type damage_t

contains

   !> Sets up the record when the deck gives &strength (strength_given);
   !> otherwise leaves it inactive.
   subroutine damage_open(dmg, deck, model)
      type(damage_t), intent(out) :: dmg            !< the record
      type(deck_t), intent(in) :: deck              !< the effective deck
      type(model_t), intent(in) :: model            !< the model
      integer :: e
      dmg%strength = strength_t(deck%xt, deck%xc, deck%yt, deck%yc, deck%s12, deck%s23)
      call delamination_open(dmg%delam, model%lmt%d, is_given(deck, 'strength', 'g2c'), deck%g2c, &
         strength_given(deck), dmg%strength, size(deck%angles), ngp*model%msh%nelem)
      dmg%delam%ratio = model%scene%impactor_mass/model%scene%plate_mass
      if (.not. strength_given(deck)) return
      dmg%active = .true.
      dmg%criterion = criterion_code(deck%criterion)
      dmg%criterion_name = deck%criterion
      call ply_stack_init(lamina_t(deck%e1, deck%e2, deck%g12, deck%g13, deck%g23, deck%nu12, deck%rho), &
                          deck%angles, deck%h, dmg%stack)
      dmg%nonlinear = model%nonlinear
      dmg%nply = size(deck%angles)
      dmg%npoint = ngp*model%msh%nelem
      allocate (dmg%d2(3, nen, ngp, model%msh%nelem))
      do e = 1, model%msh%nelem
         dmg%d2(:, :, :, e) = element_second_derivatives(model%msh%coords(:, model%msh%conn(:, e)))
      end do
      allocate (dmg%fi_max(dmg%nply, dmg%npoint), dmg%onset_time(dmg%nply, dmg%npoint), &
                dmg%d_peak(model%msh%neq), source=0.0_dp)
      allocate (dmg%mode_max(dmg%nply, dmg%npoint), source=mode_none)
      dmg%onset_time = -1.0_dp
   end subroutine damage_open

   !> At every step the history records (&output every): at each 3 x 3 Gauss point of each element
   !> (those of the membrane and bending terms, where the paper's strain gauge is, Fig. 9b) the
   !> laminate strains of d and their gradients give the stresses on both faces of every ply
   !> (in-plane from eq. 2-3, von Karman strains in the nonlinear theory; transverse shear from
   !> equilibrium), and the criterion of &strength their failure index. Kept: the step's largest
   !> index and its mode (history columns failure_index, failure_mode); per ply and point the
   !> largest index over the run, its mode (the damage map) and the first time it reached 1; the
   !> run's largest index, and the first step any index reached 1 (the onset), with its ply, mode
   !> and point.
   subroutine damage_step(dmg, model, t, d)
      type(damage_t), intent(inout) :: dmg          !< the record
      type(model_t), intent(in) :: model            !< the model
      real(dp), intent(in) :: t                     !< the time of the state (s)
      real(dp), intent(in) :: d(:)                  !< plate displacements {D}
      real(dp) :: de(nfe), e(nstate), sigma(5, 2, dmg%nply), fi(dmg%nply), mean(5, dmg%nply)
      integer :: mode(dmg%nply), el, g, p, k, kmax
      if (.not. dmg%active) return
      dmg%step_fi = -huge(1.0_dp)
      dmg%step_mode = mode_none
      kmax = 0
      elements: do el = 1, model%msh%nelem
         call gather_element(model%msh%elem_eq(:, el), d, de)
         points: do g = 1, ngp
            p = g + ngp*(el - 1)
            e = point_strain_state(model%geo(el)%dx3(:, :, g), dmg%d2(:, :, g, el), de, dmg%nonlinear)
            call ply_stresses(dmg%stack, e, sigma, mean)
            call delamination_point(dmg%delam, p, mean)
            do k = 1, 5
               dmg%smax(k) = max(dmg%smax(k), maxval(abs(sigma(k, :, :))))
            end do
            call ply_indices(dmg, sigma, fi, mode)
            plies: do k = 1, dmg%nply
               if (fi(k) > dmg%fi_max(k, p)) then
                  dmg%fi_max(k, p) = fi(k)
                  dmg%mode_max(k, p) = mode(k)
               end if
               if (fi(k) >= 1.0_dp .and. dmg%onset_time(k, p) < 0.0_dp) dmg%onset_time(k, p) = t
               if (fi(k) > dmg%step_fi) then
                  dmg%step_fi = fi(k)
                  dmg%step_mode = mode(k)
                  kmax = k + dmg%nply*(p - 1)
               end if
            end do plies
         end do points
      end do elements
      ! -- the run's largest, and the onset (the first step reaching 1)
      if (dmg%step_fi > dmg%max_fi) then
         dmg%max_fi = dmg%step_fi
         dmg%max_time = t
         dmg%max_mode = dmg%step_mode
         dmg%max_ply = 1 + mod(kmax - 1, dmg%nply)
         dmg%max_point = 1 + (kmax - 1)/dmg%nply
      end if
      if (dmg%onset < 0.0_dp .and. dmg%step_fi >= 1.0_dp) then
         dmg%onset = t
         dmg%onset_fi = dmg%step_fi
         dmg%onset_mode = dmg%step_mode
         dmg%onset_ply = 1 + mod(kmax - 1, dmg%nply)
         dmg%onset_point = 1 + (kmax - 1)/dmg%nply
      end if
   end subroutine damage_step

   !> Every step: delamination (src/strength/delamination.f90), with or without &strength: with g2c
   !> the first step whose contact force passed the threshold; with &strength, the displacements of
   !> the largest contact force so far (a copy; their stresses follow at the end).
   subroutine damage_peak(dmg, step, t, f, d)
      type(damage_t), intent(inout) :: dmg          !< the record
      integer, intent(in) :: step                   !< the step
      real(dp), intent(in) :: t, f                  !< its time (s) and contact force (N)
      real(dp), intent(in) :: d(:)                  !< plate displacements {D}
      call delamination_force(dmg%delam, t, f)
      if (.not. dmg%active .or. .not. f > dmg%peak_force) return
      dmg%peak_force = f
      dmg%peak_time = t
      dmg%peak_step = step
      dmg%d_peak = d
   end subroutine damage_peak

   !> The failure index and mode of every ply at one point: the larger of its two faces.
   pure subroutine ply_indices(dmg, sigma, fi, mode)
      type(damage_t), intent(in) :: dmg
      real(dp), intent(in) :: sigma(:,:,:)          ! (5, 2, nply)
      real(dp), intent(out) :: fi(:)
      integer, intent(out) :: mode(:)
      real(dp) :: f2(2*size(fi))
      integer :: m2(2*size(fi)), k, j
      call failure_indices(dmg%strength, dmg%criterion, reshape(sigma, [5, 2*size(fi)]), f2, m2)
      do k = 1, size(fi)
         j = merge(2*k, 2*k - 1, f2(2*k) > f2(2*k-1))
         fi(k) = f2(j)
         mode(k) = m2(j)
      end do
   end subroutine ply_indices

   !> The stresses and failure indices of every ply face at every Gauss point for the displacements
   !> d: sigma(5, 2, nply, npoint) (Pa, material axes), fi(2, nply, npoint).
   subroutine damage_stresses(dmg, model, d, sigma, fi)
      type(damage_t), intent(in) :: dmg             !< an active record
      type(model_t), intent(in) :: model            !< the model
      real(dp), intent(in) :: d(:)                  !< plate displacements {D}
      real(dp), intent(out) :: sigma(:,:,:,:)       !< (5, 2, nply, npoint) (Pa)
      real(dp), intent(out) :: fi(:,:,:)            !< (2, nply, npoint) (-)
      real(dp) :: de(nfe), e(nstate)
      integer :: el, g, p, k, f, m
      do el = 1, model%msh%nelem
         call gather_element(model%msh%elem_eq(:, el), d, de)
         do g = 1, ngp
            p = g + ngp*(el - 1)
            e = point_strain_state(model%geo(el)%dx3(:, :, g), dmg%d2(:, :, g, el), de, dmg%nonlinear)
            call ply_stresses(dmg%stack, e, sigma(:, :, :, p))
            do k = 1, dmg%nply
               do f = 1, 2
                  call failure_index(dmg%strength, dmg%criterion, sigma(:, f, k, p), fi(f, k, p), m)
               end do
            end do
         end do
      end do
   end subroutine damage_stresses

   !> The (x, y) of every Gauss point (m, from the plate centre), (2, npoint).
   function damage_points(model) result(xy)
      type(model_t), intent(in) :: model
      real(dp), allocatable :: xy(:,:)
      integer :: el
      allocate (xy(2, ngp*model%msh%nelem))
      do el = 1, model%msh%nelem
         xy(:, ngp*(el - 1) + 1:ngp*el) = model%geo(el)%xy3
      end do
   end function damage_points

   !> At the end: the summary's items (docs/OUTPUT.md lists them; failure_ply,
   !> failure_x_mm ... where damage started, or the largest index when none
   !> reached 1) and /strength in <prefix>.h5 (damage_write).
   subroutine damage_close(dmg, model, pd, s, rf, stat, errmsg)
      type(damage_t), intent(in) :: dmg             !< the record
      type(model_t), intent(in) :: model            !< the model
      type(plate_damage_t), intent(in) :: pd        !< the plies' damage (src/strength/plate_damage.f90)
      type(summary_item_t), allocatable, intent(inout) :: s(:)   !< the summary, items appended
      type(results_file_t), intent(inout) :: rf     !< written when active (its XDMF shows the ply fields)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      character(len=3), parameter :: comp(5) = [character(len=3) :: 's11', 's22', 't12', 't23', 't13']
      real(dp), allocatable :: xy(:,:)
      integer :: ply, point, mode, c, m
      stat = 0
      ! -- delamination (src/strength/delamination.f90): regime, thresholds
      call summary_text(s, 'impact_regime', impact_regime(dmg%delam%ratio))
      call summary_real(s, 'mass_ratio', 'mass_ratio', '-', dmg%delam%ratio, 1.0_dp)
      call summary_real(s, 'delamination_threshold_N', 'delamination_threshold', 'N', dmg%delam%p_c, &
                        1.0_dp, dmg%delam%threshold, 'not computed')
      call summary_real(s, 'delamination_threshold_dynamic_N', 'delamination_threshold_dynamic', &
                        'N', dmg%delam%p_dyn, 1.0_dp, dmg%delam%threshold, 'not computed')
      call summary_real(s, 'delamination_onset_us', 'delamination_onset', 's', dmg%delam%onset, &
                        1.0e6_dp, dmg%delam%threshold .and. dmg%delam%onset >= 0.0_dp, &
                        trim(merge('not reached ', 'not computed', dmg%delam%threshold)))
      if (.not. dmg%active) return
      call summary_real(s, 'max_failure_index', 'max_failure_index', '-', dmg%max_fi, 1.0_dp)
      do c = 1, 5
         call summary_real(s, 'max_abs_' // trim(comp(c)) // '_MPa', 'max_abs_' // trim(comp(c)), 'Pa', &
                           dmg%smax(c), 1.0e-6_dp)
      end do
      call summary_real(s, 'failure_onset_us', 'failure_onset', 's', dmg%onset, 1.0e6_dp, &
                        dmg%onset >= 0.0_dp, 'none')
      ply = merge(dmg%onset_ply, dmg%max_ply, dmg%onset >= 0.0_dp)
      point = merge(dmg%onset_point, dmg%max_point, dmg%onset >= 0.0_dp)
      mode = merge(dmg%onset_mode, dmg%max_mode, dmg%onset >= 0.0_dp)
      call summary_text(s, 'failure_mode', trim(mode_names(mode)))
      call summary_integer(s, 'failure_ply', ply)
      xy = damage_points(model)
      call place('failure', point)
      ! -- Choi & Chang's delamination index: the largest, its interface and place
      if (dmg%delam%interfaces) then
         call summary_real(s, 'max_delamination_index', 'max_delamination_index', '-', dmg%delam%max_index, 1.0_dp)
         call summary_integer(s, 'delamination_interface', dmg%delam%max_interface)
         call place('delamination', dmg%delam%max_point)
      end if
      if (rf%active) call damage_write(dmg, model, xy, rf, stat, errmsg)
      ! -- ply damage: the model used and why; energy dissipated; /strength/ply_damage_<mode> (nply, points)
      call summary_text(s, 'damage_model', pd%why)
      if (.not. pd%on) return
      call summary_real(s, 'damage_dissipated_J', 'damage_dissipated', 'J', pd%dissipated, 1.0_dp)
      call summary_text(s, 'damaged_ply_points', damage_counts(pd))
      do m = 1, ndmode                                  ! (and on the plies of <prefix>.xdmf)
         associate (d => reshape(pd%d(m, :, :, :), [pd%nply, size(pd%lc)]))
            if (rf%active .and. stat == 0) call h5io_write(rf%fid, 'strength/ply_damage_' // trim(dmode_names(m)), &
                                                           d, stat, errmsg)
            if (rf%xdmf%plies%active .and. stat == 0) call plies_add(rf%xdmf%plies, rf%fid, &
                                                           'ply_damage_' // trim(dmode_names(m)), d, stat, errmsg)
         end associate
      end do
   contains
      !> <what>_x_mm, <what>_y_mm of point p, 'none' without one.
      subroutine place(what, p)
         character(len=*), intent(in) :: what
         integer, intent(in) :: p
         call summary_real(s, what // '_x_mm', what // '_x', 'm', xy(1, max(p, 1)), 1.0e3_dp, p > 0, &
                           'none')
         call summary_real(s, what // '_y_mm', what // '_y', 'm', xy(2, max(p, 1)), 1.0e3_dp, p > 0, &
                           'none')
      end subroutine place
   end subroutine damage_close

   !> /strength of <prefix>.h5 (C order, as h5py shows it; its datasets and
   !> attributes: docs/OUTPUT.md, "The HDF5 file"), and /xdmf/plies.
   subroutine damage_write(dmg, model, xy, rf, stat, errmsg)
      type(damage_t), intent(in) :: dmg
      type(model_t), intent(in) :: model
      real(dp), intent(in) :: xy(:,:)
      type(results_file_t), intent(inout) :: rf
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      character(len=5), parameter :: comp(5) = [character(len=5) :: 's11', 's22', 't12', 't23', 't13']
      real(dp), allocatable :: sigma(:,:,:,:), fi(:,:,:)
      character(len=msg_len) :: why
      character(len=:), allocatable :: modes
      integer :: c, m
      why = ''
      stat = 0
      modes = ''
      do m = 0, nmode
         if (m > 0) modes = modes // ', '
         modes = modes // achar(48 + m) // ' ' // trim(mode_names(m))
      end do
      call h5io_group(rf%fid, 'strength', stat, why)
      call attr_text(rf%fid, 'strength', 'criterion', dmg%criterion_name, stat, why)
      call attr_text(rf%fid, 'strength', 'modes', modes, stat, why)
      call attr_text(rf%fid, 'strength', 'faces', 'face 2k-1: bottom of ply k (towards the impacted face), ' &
         // '2k: its top', stat, why)
      if (stat == 0) call h5io_set_attr(rf%fid, 'strength', 'plies', dmg%nply, stat, why)
      call put_data('strength/points', xy, 'm')
      if (stat == 0) call h5io_write(rf%fid, 'strength/point_element', [((c - 1)/9 + 1, c = 1, dmg%npoint)], &
                                     stat, why)
      if (stat == 0) call h5io_write(rf%fid, 'strength/ply_z', dmg%stack%z, stat, why)
      call attr_text(rf%fid, 'strength/ply_z', 'units', 'm', stat, why)
      if (stat == 0) call h5io_write(rf%fid, 'strength/ply_angle', dmg%stack%angle, stat, why)
      call attr_text(rf%fid, 'strength/ply_angle', 'units', 'deg', stat, why)
      call put_data('strength/damage_map', dmg%fi_max, '-')
      if (stat == 0) call h5io_write(rf%fid, 'strength/damage_mode', dmg%mode_max, stat, why)
      call put_data('strength/onset_time', dmg%onset_time, 's')
      if (dmg%delam%interfaces) call put_data('strength/delamination_map', dmg%delam%map, '-')
      allocate (sigma(5, 2, dmg%nply, dmg%npoint), fi(2, dmg%nply, dmg%npoint))
      call damage_stresses(dmg, model, dmg%d_peak, sigma, fi)
      if (stat == 0) call h5io_group(rf%fid, 'strength/peak', stat, why)
      if (stat == 0) call h5io_set_attr(rf%fid, 'strength/peak', 'step', dmg%peak_step, stat, why)
      call attr_unit(rf%fid, 'strength/peak', 'time', dmg%peak_time, 's', stat, why)
      call attr_unit(rf%fid, 'strength/peak', 'force', dmg%peak_force, 'N', stat, why)
      do c = 1, 5
         call put_data('strength/peak/' // trim(comp(c)), reshape(sigma(c, :, :, :), [2*dmg%nply, dmg%npoint]), 'Pa')
      end do
      call put_data('strength/peak/failure_index', reshape(fi, [2*dmg%nply, dmg%npoint]), '-')
      if (stat /= 0) then
         errmsg = rf%path // ': /strength: ' // trim(why)
         return
      end if
      ! -- the same on the laminate's grid of <prefix>.xdmf (src/results/xdmf_plies.f90)
      if (rf%xdmf%active) call plies_write(rf%xdmf%plies, rf%fid, model%msh, ply_maps_t(dmg%stack%z, &
         dmg%stack%angle, dmg%fi_max, dmg%mode_max, dmg%onset_time, sigma, fi, dmg%delam%map, modes), stat, why)
      if (stat /= 0) errmsg = rf%path // ': /xdmf/plies: ' // trim(why)
   contains
      subroutine put_data(name, x, units)
         character(len=*), intent(in) :: name, units
         real(dp), intent(in) :: x(:,:)
         if (stat == 0) call h5io_write(rf%fid, name, x, stat, why)
         call attr_text(rf%fid, name, 'units', units, stat, why)
      end subroutine put_data
   end subroutine damage_write

end module damage_record
