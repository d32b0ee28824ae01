!> navier_impact: the Navier modal solution of an impact on a simply
!> supported plate (validation/navier_impact_solution.f90), the reference
!> for ./impact's dynamic point response on the same deck.
!>
!> Usage (from the repository root, after `make navier-impact`):
!>
!>     build/navier_impact deck.nml [--load hertz|point] [--mmax N]
!>                        [--max-mmax N] [--tol X] [--out prefix]
!>
!>   --load     'hertz' (default): the contact force spread over the contact
!>              disc with Hertz's pressure; 'point': the paper's point force,
!>              whose Mindlin series does not converge in modes
!>   --mmax N   one run with every odd m, n <= N (and one at half as many
!>              half-wave numbers per direction, for the change); without
!>              it, the number of half-wave numbers per direction is doubled
!>              from 16 (mmax = 31, 63, 127, ...) until the first-contact
!>              peak force, its time and the end of the first contact change
!>              by less than --tol (default 1e-4) relative, at most up to
!>              --max-mmax (default 2047)
!>   --out      prefix of the result files (default: the deck's &output
!>              prefix followed by '_navier_hertz' or '_navier_point')
!>
!> It reads the deck's &plate, &lamina, &laminate, &impactor, &contact and
!> &analysis (dt, t_end); &boundary edges must be 'simply_supported' and
!> the impact at the centre. The solution is linear (FSDT, rotary inertia)
!> with D16 = D26 = 0 whatever &analysis theory and &mesh say: compare it
!> with ./impact run with theory = 'linear' on a quarter (or averaged) plate.
!>
!> Writes, replacing earlier ones:
!>   <prefix>_history.dat      the run with the most modes, one row per step
!>   <prefix>_summary.dat      key = value lines (./impact's keys where the
!>                             quantity is the same; coarse_* the figures at
!>                             the coarser mode count, change_* the relative
!>                             changes)
!>   <prefix>_convergence.dat  one row per mode count
!> Exit status 1 on bad input or a failed run; a series that did not
!> converge within --max-mmax is reported (mode_converged = false), not an
!> error.
program navier_impact
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use kinds, only: dp, msg_len
   use input_deck, only: deck_t, read_deck_file
   use deck_echo, only: echo_deck
   use result_files, only: write_column_block
   use file_system, only: make_directories
   use navier_impact_solution, only: navier_problem_t, navier_result_t, navier_problem_from_deck, &
      navier_impact_run, navier_changes, load_hertz, load_point, load_name, nchange, change_names
   implicit none

   !> Half-wave numbers per direction of the first run of the doubling.
   integer, parameter :: first_count = 16
   !> Default relative change below which the series counts as converged.
   real(dp), parameter :: default_tol = 1.0e-4_dp
   !> Default largest half-wave number of the doubling.
   integer, parameter :: default_max_mmax = 2047

   type(deck_t) :: deck
   type(navier_problem_t) :: problem
   type(navier_result_t) :: coarse, fine
   character(len=4096) :: deck_path, prefix, arg
   character(len=msg_len) :: errmsg
   real(dp) :: tol, change(nchange), total_cpu
   integer :: load, mmax_fixed, max_mmax, iarg, stat, count, mmax, level, conv_unit, c
   logical :: converged, have_coarse
   character(len=:), allocatable :: status

   ! =====================================================================
   ! Command line and deck
   ! =====================================================================
   deck_path = ''
   prefix = ''
   load = load_hertz
   mmax_fixed = 0
   max_mmax = default_max_mmax
   tol = default_tol
   iarg = 1
   options: do while (iarg <= command_argument_count())
      call get_command_argument(iarg, arg)
      select case (arg)
      case ('--load')
         call option_value(arg)
         select case (arg)
         case ('hertz')
            load = load_hertz
         case ('point')
            load = load_point
         case default
            call fail("--load "//trim(arg)//": 'hertz' or 'point'")
         end select
      case ('--mmax')
         call option_value(arg)
         mmax_fixed = integer_value('--mmax', arg)
      case ('--max-mmax')
         call option_value(arg)
         max_mmax = integer_value('--max-mmax', arg)
      case ('--tol')
         call option_value(arg)
         read (arg, *, iostat=stat) tol
         if (stat /= 0 .or. .not. (tol > 0.0_dp .and. tol < 1.0_dp)) call fail('--tol '//trim(arg)// &
            ': a number in (0, 1)')
      case ('--out')
         call option_value(arg)
         prefix = arg
      case default
         if (arg(1:1) == '-') call fail('unknown option '//trim(arg)//' (usage: navier_impact deck.nml '// &
            '[--load hertz|point] [--mmax N] [--max-mmax N] [--tol X] [--out prefix])')
         if (len_trim(deck_path) > 0) call fail('one deck only: '//trim(deck_path)//' and '//trim(arg))
         deck_path = arg
      end select
      iarg = iarg + 1
   end do options
   if (len_trim(deck_path) == 0) call fail('no deck (usage: navier_impact deck.nml [--load hertz|point] '// &
      '[--mmax N] [--max-mmax N] [--tol X] [--out prefix])')

   call read_deck_file(trim(deck_path), deck, stat, errmsg)
   if (stat /= 0) call fail('input: '//errmsg)
   call navier_problem_from_deck(deck, load, problem, stat, errmsg)
   if (stat /= 0) call fail(errmsg)
   if (len_trim(prefix) == 0) prefix = trim(deck%prefix)//'_navier_'//load_name(load)
   call echo_problem(output_unit)

   ! =====================================================================
   ! Mode counts: doubled until the first contact has converged, or the
   ! count asked for and half of it
   ! =====================================================================
   call make_parent_directory(trim(prefix))
   open (newunit=conv_unit, file=trim(prefix)//'_convergence.dat', status='replace', action='write', &
         iostat=stat, iomsg=errmsg)
   if (stat /= 0) call fail('cannot write '//trim(prefix)//'_convergence.dat: '//trim(errmsg))
   call convergence_header(conv_unit)
   write (output_unit, '(a)') '    mmax    modes  F_peak1 (N)  t_peak1 (us)  end1 (us)  w_max (mm)' // &
      '    cpu (s)   change: F_peak1  t_peak1    end1     w_max'

   converged = .false.
   have_coarse = .false.
   total_cpu = 0.0_dp
   if (mmax_fixed > 0) then
      count = max(1, ((mmax_fixed + 1)/2)/2)
   else
      count = first_count
   end if
   level = 0
   mode_counts: do
      level = level + 1
      mmax = 2*count - 1
      if (level > 1) then
         coarse = fine
         have_coarse = .true.
      end if
      call navier_impact_run(problem, mmax, fine, stat, errmsg)
      if (stat /= 0) call fail('mmax = '//int_text(mmax)//': '//errmsg)
      total_cpu = total_cpu + fine%cpu_s
      change = -1.0_dp
      if (have_coarse) change = navier_changes(coarse, fine)
      call level_row(output_unit, conv_unit, fine, change)
      if (have_coarse) converged = all(change(1:3) < tol)
      if (mmax_fixed > 0) then
         if (level == 2) exit mode_counts
         count = (mmax_fixed + 1)/2
      else
         if (converged) exit mode_counts
         if (4*count - 1 > max_mmax) exit mode_counts
         count = 2*count
      end if
   end do mode_counts
   close (conv_unit)

   if (mmax_fixed > 0) then
      status = 'fixed mmax'
   else if (converged) then
      status = 'converged'
   else
      status = 'not converged within max-mmax = '//int_text(max_mmax)
   end if

   ! =====================================================================
   ! Results of the run with the most modes
   ! =====================================================================
   call write_history(trim(prefix)//'_history.dat', fine)
   call write_summary_file(trim(prefix)//'_summary.dat')
   write (output_unit, '(a)') 'modes: '//status//'; mmax = '//int_text(fine%mmax)//', '// &
      int_text(fine%modes)//' modes'
   if (have_coarse) write (output_unit, '(a,4(1x,a,es9.2))') 'last change (relative), from mmax = '// &
      int_text(coarse%mmax)//':', (trim(change_names(c))//' =', change(c), c = 1, nchange)
   write (output_unit, '(a,f9.2,a)') 'cpu, all mode counts: ', total_cpu, ' s'
   write (output_unit, '(a)') 'history: '//trim(prefix)//'_history.dat'
   write (output_unit, '(a)') 'summary: '//trim(prefix)//'_summary.dat'
   write (output_unit, '(a)') 'convergence: '//trim(prefix)//'_convergence.dat'
   flush (output_unit)
   if (.not. converged .and. mmax_fixed == 0) write (error_unit, '(a)') 'navier_impact: warning: the '// &
      load_name(load)//' series did not converge within --max-mmax '//int_text(max_mmax)// &
      ' (relative tolerance '//real_text(tol)//')'

contains

   !> Stops with one line on standard error.
   subroutine fail(message)
      character(len=*), intent(in) :: message     !< what is wrong
      write (error_unit, '(a)') 'navier_impact: error: '//trim(message)
      error stop 1
   end subroutine fail

   !> The value after option arg (the next argument).
   subroutine option_value(arg)
      character(len=*), intent(inout) :: arg      !< the option in, its value out
      character(len=len(arg)) :: option
      option = arg
      iarg = iarg + 1
      if (iarg > command_argument_count()) call fail(trim(option)//' needs a value')
      call get_command_argument(iarg, arg)
   end subroutine option_value

   !> A positive integer option value.
   function integer_value(option, text) result(n)
      character(len=*), intent(in) :: option      !< the option, for the message
      character(len=*), intent(in) :: text        !< its value
      integer :: n
      integer :: ios
      read (text, *, iostat=ios) n
      if (ios /= 0 .or. n < 1) call fail(option//' '//trim(text)//': a positive integer')
   end function integer_value

   !> The effective input and the derived quantities.
   subroutine echo_problem(u)
      integer, intent(in) :: u                    !< unit
      write (u, '(a)') 'navier_impact: Navier modal impact solution, simply supported plate ' // &
         '(linear FSDT, rotary inertia, D16 = D26 = 0)'
      call echo_deck(deck, u, '')
      if (deck%theory /= 'linear') write (u, '(a)') "note: &analysis theory = '"//trim(deck%theory)// &
         "' is not used: this solution is linear (compare with ./impact run with theory = 'linear')"
      write (u, '(a,4es12.4)') 'laminate: D11 D22 D12 D66 (N m)  ', problem%lmt%d(1,1), problem%lmt%d(2,2), &
         problem%lmt%d(1,2), problem%lmt%d(3,3)
      write (u, '(a,2es12.4)') 'laminate: Abar44 Abar55 (N/m)    ', problem%lmt%as(1,1), problem%lmt%as(2,2)
      write (u, '(a,2es12.4)') 'laminate: P (kg/m^2), I (kg)      ', problem%lmt%p, problem%lmt%i
      write (u, '(a,a,a,es10.3,a,es10.3,a,i0)') 'load: ', load_name(load), ', nose radius R = ', &
         problem%radius, ' m; dt = ', problem%dt, ' s, steps ', nint(problem%t_end/problem%dt)
   end subroutine echo_problem

   !> Header of <prefix>_convergence.dat.
   subroutine convergence_header(u)
      integer, intent(in) :: u                    !< unit
      integer, parameter :: ncol = 14
      character(len=28), parameter :: names(ncol) = [character(len=28) :: 'mmax', 'modes', &
         'first_peak_force_N', 'first_peak_time_us', 'first_contact_end_us', 'max_deflection_mm', &
         'peak_force_N', 'time_of_peak_us', 'contact_duration_us', 'cpu_s', &
         'change_first_peak_force', 'change_first_peak_time', 'change_first_contact_end', &
         'change_max_deflection']
      character(len=72), parameter :: text(ncol) = [character(len=72) :: &
         'largest half-wave number, odd m, n <= mmax (-)', 'modes, 3 per (m, n) (-)', &
         'largest force of the first contact (N)', &
         'its time, parabola through the steps about it (us)', &
         'end of the first contact, alpha = alpha_0 interpolated in the step (us)', &
         'largest centre deflection (mm)', 'largest force of the run (N)', 'its step time (us)', &
         'first contact duration, step times as ./impact (us)', 'cpu time of the run (s)', &
         'relative change of column 3 from the previous row (-1: first row)', &
         'relative change of column 4 (-)', 'relative change of column 5 (-)', &
         'relative change of column 6 (-)']
      write (u, '(a)') '# navier_impact: convergence in modes, load '//load_name(load)//', deck '// &
         trim(deck%source)
      call write_column_block(u, names, text)
   end subroutine convergence_header

   !> One mode count: a line on the terminal and a row of the convergence file.
   subroutine level_row(u, cu, r, change)
      integer, intent(in) :: u, cu                !< terminal, convergence file
      type(navier_result_t), intent(in) :: r      !< the run
      real(dp), intent(in) :: change(nchange)     !< relative changes (-1: none)
      write (u, '(i8,i9,f13.4,f14.4,f11.4,f12.6,f11.2,3x,4es10.2)') r%mmax, r%modes, r%first_peak_force, &
         r%first_peak_time_interp*1.0e6_dp, end_time(r)*1.0e6_dp, r%s%max_deflection*1.0e3_dp, r%cpu_s, change
      write (cu, '(2i9,es16.8,2f14.6,es16.8,es16.8,2f12.4,f10.2,4es12.4)') r%mmax, r%modes, r%first_peak_force, &
         r%first_peak_time_interp*1.0e6_dp, end_time(r)*1.0e6_dp, r%s%max_deflection*1.0e3_dp, &
         r%s%peak_force, r%s%time_of_peak*1.0e6_dp, duration(r)*1.0e6_dp, r%cpu_s, change
      flush (u)
      flush (cu)
   end subroutine level_row

   !> End of the first contact, interpolated; the run's end when it has not ended (s).
   pure function end_time(r) result(t)
      type(navier_result_t), intent(in) :: r      !< the run
      real(dp) :: t
      t = r%first_end_interp
      if (t < 0.0_dp) t = r%time(r%nstep)
   end function end_time

   !> ./impact's contact_duration: first contact end - start in step
   !> times, or the time in contact so far when it has not ended (s).
   pure function duration(r) result(d)
      type(navier_result_t), intent(in) :: r      !< the run
      real(dp) :: d
      d = 0.0_dp
      if (r%s%contacts >= 1) then
         if (r%s%first_contact_end >= 0.0_dp) then
            d = r%s%first_contact_end - r%s%first_contact_start
         else
            d = r%time(r%nstep) - r%s%first_contact_start
         end if
      end if
   end function duration

   !> <prefix>_history.dat of run r.
   subroutine write_history(path, r)
      character(len=*), intent(in) :: path        !< file
      type(navier_result_t), intent(in) :: r      !< the run
      integer, parameter :: ncol = 11
      character(len=18), parameter :: names(ncol) = [character(len=18) :: 'time_us', 'force_N', &
         'indentation_mm', 'w_plate_mm', 'w_centre_mm', 'w_impactor_mm', 'v_impactor_m_s', &
         'contact_radius_mm', 'energy_error_J', 'branch', 'evaluations']
      character(len=88), parameter :: text(ncol) = [character(len=88) :: 'time (us)', &
         'contact force F (N)', 'indentation alpha = w_impactor - w_plate, eq. (13) (mm)', &
         'plate deflection weighted by the contact pressure (1/F) int p w dA; point: centre (mm)', &
         'plate centre deflection (mm)', 'impactor displacement since first touch (mm)', &
         'impactor velocity, + towards the plate (m/s)', 'contact radius sqrt(R alpha), 0 without contact (mm)', &
         'E0 - (impactor + plate energy + int F d(alpha)) (J)', &
         'contact law branch: 0 none, 1 loading, 2 unloading, 3 reloading (-)', &
         'evaluations of the contact equation in the step (-)']
      integer :: u, i, ios
      character(len=msg_len) :: iomsg
      open (newunit=u, file=path, status='replace', action='write', iostat=ios, iomsg=iomsg)
      if (ios /= 0) call fail('cannot write '//path//': '//trim(iomsg))
      write (u, '(a)') '# navier_impact: history, Navier modal solution, load '//load_name(r%load)// &
         ', mmax = '//int_text(r%mmax)//', '//int_text(r%modes)//' modes'
      call echo_deck(deck, u, '# ')
      call write_column_block(u, names, text)
      rows: do i = 0, r%nstep
         write (u, '(f12.4,8es16.7e3,2i4)') r%time(i)*1.0e6_dp, r%force(i), r%alpha(i)*1.0e3_dp, &
            r%w_plate(i)*1.0e3_dp, r%w_centre(i)*1.0e3_dp, r%w_impactor(i)*1.0e3_dp, r%v_impactor(i), &
            r%contact_radius(i)*1.0e3_dp, r%energy_error(i), r%branch(i), r%iterations(i)
      end do rows
      close (u)
   end subroutine write_history

   !> <prefix>_summary.dat: the run with the most modes, the coarser one
   !> (coarse_*) and the relative changes (change_*).
   subroutine write_summary_file(path)
      character(len=*), intent(in) :: path        !< file
      integer :: u, ios, c
      character(len=msg_len) :: iomsg
      open (newunit=u, file=path, status='replace', action='write', iostat=ios, iomsg=iomsg)
      if (ios /= 0) call fail('cannot write '//path//': '//trim(iomsg))
      write (u, '(a)') '# navier_impact: summary (key = value; units in the key names)'
      call echo_deck(deck, u, '# ')
      write (u, '(a)') 'status = '//status
      write (u, '(a)') 'solution = navier_modal'
      write (u, '(a)') 'theory = linear'
      write (u, '(a)') 'load = '//load_name(load)
      call write_figures(u, '', fine)
      write (u, '(a,es10.3)') 'mode_tolerance = ', tol
      write (u, '(a)') 'mode_converged = '//trim(merge('true ', 'false', converged))
      if (have_coarse) then
         do c = 1, nchange
            write (u, '(a,es12.4)') 'change_'//trim(change_names(c))//' = ', change(c)
         end do
         call write_figures(u, 'coarse_', coarse)
      end if
      write (u, '(a,f12.4)') 'total_cpu_s = ', total_cpu
      close (u)
   end subroutine write_summary_file

   !> The figures of one run as key = value lines, keys prefixed by key0.
   subroutine write_figures(u, key0, r)
      integer, intent(in) :: u                    !< unit
      character(len=*), intent(in) :: key0        !< '' or 'coarse_'
      type(navier_result_t), intent(in) :: r      !< the run
      logical :: ended
      ended = r%s%contacts == 0 .or. r%s%first_contact_end >= 0.0_dp
      write (u, '(a,i0)')     key0//'mmax = ', r%mmax
      write (u, '(a,i0)')     key0//'pairs = ', r%pairs
      write (u, '(a,i0)')     key0//'modes = ', r%modes
      write (u, '(a,es15.7)') key0//'peak_force_N = ', r%s%peak_force
      write (u, '(a,f12.4)')  key0//'time_of_peak_us = ', r%s%time_of_peak*1.0e6_dp
      write (u, '(a,f12.4)')  key0//'contact_duration_us = ', duration(r)*1.0e6_dp
      write (u, '(a,a)')      key0//'first_contact_ended = ', trim(merge('true ', 'false', ended))
      write (u, '(a,i0)')     key0//'contacts = ', r%s%contacts
      write (u, '(a,es15.7)') key0//'max_deflection_mm = ', r%s%max_deflection*1.0e3_dp
      write (u, '(a,es15.7)') key0//'first_contact_peak_force_N = ', r%first_peak_force
      write (u, '(a,f12.4)')  key0//'first_contact_peak_time_us = ', r%first_peak_time*1.0e6_dp
      write (u, '(a,f12.4)')  key0//'first_contact_peak_time_interp_us = ', r%first_peak_time_interp*1.0e6_dp
      write (u, '(a,f12.4)')  key0//'first_contact_start_us = ', r%s%first_contact_start*1.0e6_dp
      write (u, '(a,f12.4)')  key0//'first_contact_end_us = ', r%s%first_contact_end*1.0e6_dp
      write (u, '(a,f12.4)')  key0//'first_contact_end_interp_us = ', r%first_end_interp*1.0e6_dp
      write (u, '(a,es15.7)') key0//'max_w_plate_mm = ', r%max_w_plate*1.0e3_dp
      write (u, '(a,es15.7)') key0//'max_contact_radius_mm = ', r%max_contact_radius*1.0e3_dp
      write (u, '(a,es15.7)') key0//'permanent_indentation_mm = ', r%s%permanent_indentation*1.0e3_dp
      write (u, '(a,es15.7)') key0//'rebound_velocity_m_s = ', -r%s%final_velocity
      write (u, '(a,es15.7)') key0//'initial_energy_J = ', r%s%initial_energy
      write (u, '(a,es15.7)') key0//'max_energy_error_J = ', r%s%max_energy_error
      write (u, '(a,i0)')     key0//'steps = ', r%s%steps
      write (u, '(a,i0)')     key0//'evaluations = ', r%evaluations
      write (u, '(a,i0)')     key0//'max_evaluations_per_step = ', r%max_evaluations
      write (u, '(a,i0)')     key0//'evaluations_beyond_table = ', r%beyond_table
      write (u, '(a,f12.4)')  key0//'cpu_s = ', r%cpu_s
   end subroutine write_figures

   !> The directory part of a path prefix and its parents, made where
   !> missing (nothing if none; a failure shows when the file is opened).
   subroutine make_parent_directory(path)
      character(len=*), intent(in) :: path        !< file path prefix
      integer :: slash, st
      character(len=msg_len) :: why
      why = ''
      slash = index(path, '/', back=.true.)
      if (slash > 1) call make_directories(path(1:slash-1), st, why)
   end subroutine make_parent_directory

   !> An integer as text.
   pure function int_text(n) result(text)
      integer, intent(in) :: n                    !< the number
      character(len=:), allocatable :: text
      character(len=16) :: buf
      write (buf, '(i0)') n
      text = trim(buf)
   end function int_text

   !> A real in a short form.
   pure function real_text(x) result(text)
      real(dp), intent(in) :: x                   !< the number
      character(len=:), allocatable :: text
      character(len=24) :: buf
      write (buf, '(es10.2)') x
      text = trim(adjustl(buf))
   end function real_text

end program navier_impact
