!> The runs of the other analyses of the same model (&analysis kind):
!> static, modes and pressure, each solved by its module (what the
!> validation and the tests call), its result files and report written here.
!> Each checks a part of the model on its own (docs/VALIDATION.md).
module other_analyses
   use kinds, only: dp, msg_len
   use number_text, only: int_str
   use deck_schema, only: deck_t
   use plate_model, only: model_t, gather_element
   use mesh, only: ndof_node
   use analysis_load, only: assemble_load
   use result_files, only: open_columns
   use static_analysis, only: static_result_t, static_solve
   use modal_analysis, only: modal_result_t, modal_solve
   use pressure_analysis, only: pressure_result_t, pressure_solve
   implicit none
   private
   public :: run_other_analysis

contains

   !> Runs the analysis of deck%analysis_kind on the model; its report (a
   !> few lines) goes to unit.
   subroutine run_other_analysis(deck, model, unit, stat, errmsg)
      type(deck_t), intent(in) :: deck              !< the deck
      type(model_t), intent(in) :: model            !< the model
      integer, intent(in) :: unit                   !< where the report goes
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      character(len=2048) :: report
      real(dp), allocatable :: f(:)
      report = ''
      stat = 0
      if (deck%analysis_kind == 'static' .or. deck%analysis_kind == 'pressure') then
         allocate (f(model%msh%neq))
         call assemble_load(deck, model, f, stat, errmsg)
         if (stat /= 0) return
      end if
      select case (deck%analysis_kind)
      case ('static');   call run_static(deck, model, f, report, stat, errmsg)
      case ('modes');    call run_modes(deck, model, report, stat, errmsg)
      case ('pressure'); call run_pressure(deck, model, f, report, stat, errmsg)
      end select
      if (len_trim(report) > 0) write (unit, '(a)') trim(report)
   end subroutine run_other_analysis

   !> The static analysis under the load f: solution (static_solve), result
   !> files; the report is a line for the terminal.
   subroutine run_static(deck, model, f, report, stat, errmsg)
      type(deck_t), intent(in) :: deck              !< the deck
      type(model_t), intent(in) :: model            !< the model
      real(dp), intent(in) :: f(:)                  !< the load vector of &load (N)
      character(len=*), intent(inout) :: report     !< the report for the terminal ('' when none)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      type(static_result_t) :: res
      character(len=msg_len) :: load_unit, solve_msg
      integer :: u, inc, n, solve_stat, k
      real(dp) :: de(ndof_node)
      n = merge(deck%load_increments, 1, model%nonlinear)
      solve_msg = ''
      call static_solve(model, f, n, res, solve_stat, solve_msg)

      load_unit = merge('N ', 'Pa', deck%load_kind == 'central_force')
      call open_columns(deck, '_static.dat', 'impact: static analysis, load-deflection path', &
         [character(len=16) :: 'increment', 'load_factor', 'load', 'w_centre_mm', 'w_centre_h', &
          'iterations', 'residual'], &
         [character(len=80) :: 'load increment (-)', 'load factor lambda (-)', &
          'pressure q0 (Pa) or central force (N): lambda * &load magnitude, in '//trim(load_unit), &
          'deflection at the plate centre (mm)', 'centre deflection / thickness (-)', &
          'Newton iterations (linear: 1 solve) (-)', '|lambda F - f_int| / |lambda F| at the end (-)'], &
         u, stat, errmsg)
      if (stat /= 0) return
      rows: do inc = 0, res%increments
         write (u, '(i6, f12.6, 3es16.7e3, i6, es12.3e3)') inc, res%load_factor(inc), &
            res%load_factor(inc)*deck%load_magnitude, res%w_centre(inc)*1.0e3_dp, &
            res%w_centre(inc)/deck%h, res%iterations(inc), res%residual(inc)
      end do rows
      close (u)

      call open_columns(deck, '_deflection.dat', 'impact: static analysis, nodal displacements ' // &
         'at the last load reached (modelled domain)', &
         [character(len=12) :: 'node', 'x_mm', 'y_mm', 'u_mm', 'v_mm', 'w_mm', 'psi_x_rad', 'psi_y_rad'], &
         [character(len=40) :: 'node (-)', 'x from the plate centre (mm)', 'y from the plate centre (mm)', &
          'in-plane displacement u (mm)', 'in-plane displacement v (mm)', 'deflection w (mm)', &
          'rotation psi_x (rad)', 'rotation psi_y (rad)'], u, stat, errmsg)
      if (stat /= 0) return
      nodes: do k = 1, model%msh%nnode
         call gather_element(model%msh%eq(:, k), res%d, de)
         write (u, '(i6, 2f12.4, 5es16.7e3)') k, model%msh%coords(:, k)*1.0e3_dp, de(1:3)*1.0e3_dp, de(4:5)
      end do nodes
      close (u)

      write (report, '(a,es12.5,a,a,a,es12.5,a,f9.4,a)') 'static: load ', &
         res%load_factor(res%increments)*deck%load_magnitude, ' ', trim(load_unit), &
         ': centre deflection ', res%w_centre(res%increments)*1.0e3_dp, ' mm (w/h = ', &
         res%w_centre(res%increments)/deck%h, ')' // new_line('a') // 'results: ' // deck%prefix // &
         '_static.dat, ' // deck%prefix // '_deflection.dat'
      stat = solve_stat
      if (stat /= 0) errmsg = solve_msg
   end subroutine run_static

   !> The modal analysis: solution (modal_solve) and result files; the
   !> report is a few lines for the terminal.
   subroutine run_modes(deck, model, report, stat, errmsg)
      type(deck_t), intent(in) :: deck              !< the deck
      type(model_t), intent(in) :: model            !< the model
      character(len=*), intent(inout) :: report     !< the report for the terminal ('' when none)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      type(modal_result_t) :: res
      character(len=16), allocatable :: names(:)
      character(len=48), allocatable :: texts(:)
      real(dp), allocatable :: w(:,:)
      real(dp) :: wmax(deck%mode_count), fraction(3)
      character(len=23) :: fmt
      integer :: u, j, k
      call modal_solve(model, deck%mode_count, deck%mode_shapes, res, stat, errmsg)
      if (stat /= 0) return

      call open_columns(deck, '_modes.dat', 'impact: modal analysis, K_L phi = omega^2 M phi (LAPACK dsbgvx)', &
         [character(len=18) :: 'mode', 'frequency_Hz', 'omega_rad_s', 'w_fraction', 'inplane_fraction', &
          'rotation_fraction'], &
         [character(len=64) :: 'mode number, ascending frequency (-)', 'natural frequency (Hz)', &
          'circular frequency (rad/s)', 'kinetic energy share of w (-; -1: no shapes)', &
          'kinetic energy share of u, v (-; -1: no shapes)', 'kinetic energy share of psi_x, psi_y (-; -1: no shapes)'], &
         u, stat, errmsg)
      if (stat /= 0) return
      fraction = -1.0_dp                            ! without the shapes
      fmt = merge('(i6, 2es17.8e3, 3f12.6)', '(i6, 2es17.8e3, 3f12.1)', deck%mode_shapes)
      rows: do j = 1, res%count
         if (deck%mode_shapes) fraction = res%fraction(:, j)
         write (u, fmt) j, res%freq(j), sign(sqrt(abs(res%omega2(j))), res%omega2(j)), fraction
      end do rows
      close (u)
      if (.not. deck%mode_shapes) then
         write (report, '(a,i0,a,es13.6,a,es13.6,a)') 'modes: ', res%count, ' frequencies from ', res%freq(1), &
            ' to ', res%freq(res%count), ' Hz (no shapes: &modes shapes = .false.)' // new_line('a') // &
            'results: ' // deck%prefix // '_modes.dat'
         return
      end if

      ! -- mode shapes: w at the nodes, each mode scaled to max |w| = 1
      allocate (names(2 + res%count), texts(2 + res%count), w(model%msh%nnode, res%count))
      names(1) = 'x_mm';  texts(1) = 'x from the plate centre (mm)'
      names(2) = 'y_mm';  texts(2) = 'y from the plate centre (mm)'
      do j = 1, res%count
         write (names(2 + j), '(a,i0)') 'w_mode_', j
         write (texts(2 + j), '(a,i0,a)') 'w of mode ', j, ', largest |w| = 1 (-)'
         call gather_element(model%msh%eq(3, :), res%shapes(:, j), w(:, j))    ! w: freedom 3
         wmax(j) = maxval(abs(w(:, j)))
         if (wmax(j) == 0.0_dp) wmax(j) = 1.0_dp
      end do
      call open_columns(deck, '_mode_shapes.dat', 'impact: modal analysis, mode shapes (modelled domain)', &
         names, texts, u, stat, errmsg)
      if (stat /= 0) return
      nodes: do k = 1, model%msh%nnode
         write (u, '(2f12.4, *(f11.6))') model%msh%coords(:, k)*1.0e3_dp, w(k, :)/wmax(:res%count)
      end do nodes
      close (u)

      write (report, '(a,i0,a,es13.6,a,es13.6,a)') 'modes: ', res%count, ' frequencies from ', res%freq(1), &
         ' to ', res%freq(res%count), ' Hz' // new_line('a') // 'results: ' // deck%prefix // '_modes.dat, ' &
         // deck%prefix // '_mode_shapes.dat'
   end subroutine run_modes

   !> The transient analysis under the load f: time integration
   !> (pressure_solve), history file; the report is a few lines for the terminal.
   subroutine run_pressure(deck, model, f, report, stat, errmsg)
      type(deck_t), intent(in) :: deck              !< the deck
      type(model_t), intent(in) :: model            !< the model
      real(dp), intent(in) :: f(:)                  !< the load vector of &load (N)
      character(len=*), intent(inout) :: report     !< the report for the terminal ('' when none)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      type(pressure_result_t) :: res
      integer :: u, step, nstep, peak
      nstep = nint(deck%t_end/deck%dt)
      call pressure_solve(model, f, deck%dt, nstep, deck%every, res, stat, errmsg)
      if (stat /= 0) return

      call open_columns(deck, '_pressure_history.dat', &
         'impact: transient response to a load applied at t = 0 and held', &
         [character(len=16) :: 'time_us', 'w_centre_mm', 'ke_plate_J', 'strain_energy_J', 'work_J', &
          'energy_error_J', 'plate_solves'], &
         [character(len=64) :: 'time (us)', 'deflection at the plate centre (mm)', &
          'plate kinetic energy, whole plate (J)', 'plate strain energy, whole plate (J)', &
          'work of the load F . D, whole plate (J)', 'work - kinetic - strain energy (J)', &
          'plate solutions of the step, eq. (18)-(19) (-)'], u, stat, errmsg)
      if (stat /= 0) return
      rows: do step = 0, res%nstep
         if (mod(step, deck%every) /= 0 .and. step /= res%nstep) cycle rows
         write (u, '(f14.4, 5es16.7e3, i6)') res%t(step)*1.0e6_dp, res%w_centre(step)*1.0e3_dp, &
            res%kinetic(step), res%strain(step), res%work(step), &
            res%work(step) - res%kinetic(step) - res%strain(step), res%iterations(step)
      end do rows
      close (u)

      peak = maxloc(abs(res%w_centre), dim=1) - 1
      write (report, '(a,i0,a,es12.5,a,f12.3,a)') 'pressure: ', res%nstep, ' steps; largest centre deflection ', &
         res%w_centre(peak)*1.0e3_dp, ' mm at ', res%t(peak)*1.0e6_dp, ' us' // new_line('a') // &
         'results: ' // deck%prefix // '_pressure_history.dat'
      if (res%unconverged > 0) report = trim(report) // new_line('a') // 'warning: ' &
         // int_str(res%unconverged) // ' steps did not meet eq. (18) within max_nonlinear_iter'
   end subroutine run_pressure

end module other_analyses
