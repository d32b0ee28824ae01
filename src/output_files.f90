!> Result files: the history (one row per output step) and the summary.
!>
!> <prefix>_history.dat: column text for gnuplot. The header echoes the
!> effective deck (lines starting '# '), then lists every column with its
!> unit, then the column names on one '#' line. Columns:
!>    1 time_us               time (us)
!>    2 force_N               contact force on the whole plate, F (N)
!>    3 indentation_mm        alpha = w_impactor - w_plate, eq. (13) (mm)
!>    4 w_plate_mm            plate deflection at the impact point (mm)
!>    5 w_impactor_mm         impactor displacement since first touch (mm)
!>    6 v_impactor_m_s        impactor velocity, positive towards the plate (m/s)
!>    7 strain_y_back         in-plane y strain on the back face at the gauge (-)
!>    8 ke_impactor_J         impactor kinetic energy (J)
!>    9 ke_plate_J            plate kinetic energy, whole plate (J)
!>   10 strain_energy_J       plate strain energy, whole plate (J)
!>   11 contact_work_J        work of the contact force on the plate (J)
!>   12 indentation_energy_J  int F d alpha: stored in and dissipated by the contact (J)
!>   13 energy_error_J        E0 - (8 + 9 + 10 + 12): energy the integration lost (+) or made (-) (J)
!>   14 branch                contact law branch: 0 none, 1 loading, 2 unloading, 3 reloading
!>   15 contact_iter          contact-force iterations of the step, eq. (17)
!>   16 nonlinear_iter        plate solutions of the step (eq. 19 iterations, all contact iterations)
!> Rows are flushed as they are written, so a run that stops early leaves a
!> valid file up to its last step.
!>
!> <prefix>_summary.dat: 'key = value' lines (see write_summary).
!>
!> Nothing lost: before any work (check_output) the run makes sure it can
!> write <prefix>_history.dat and refuses to start when <prefix>_history.dat,
!> <prefix>_summary.dat or <prefix>.h5 (&output hdf5) exists, the results of
!> another run, unless the deck says &output overwrite = .true. (or the
!> command line --overwrite).
module output_files
   use kinds, only: dp, msg_len
   use input_deck, only: deck_t, echo_deck
   implicit none
   private
   public :: history_row_t, run_summary_t, open_history, write_history_row, &
             summary_record, write_summary, ncol, check_output

   !> Names of the result files: <prefix> followed by these.
   character(len=*), parameter :: history_suffix = '_history.dat', summary_suffix = '_summary.dat'
   !> Number of history columns.
   integer, parameter :: ncol = 16
   character(len=20), parameter :: col_name(ncol) = [character(len=20) :: &
      'time_us', 'force_N', 'indentation_mm', 'w_plate_mm', 'w_impactor_mm', &
      'v_impactor_m_s', 'strain_y_back', 'ke_impactor_J', 'ke_plate_J', &
      'strain_energy_J', 'contact_work_J', 'indentation_energy_J', 'energy_error_J', &
      'branch', 'contact_iter', 'nonlinear_iter']
   character(len=64), parameter :: col_text(ncol) = [character(len=64) :: &
      'time (us)', 'contact force, whole plate (N)', 'indentation alpha, eq. (13) (mm)', &
      'plate deflection at the impact point (mm)', 'impactor displacement (mm)', &
      'impactor velocity, + towards the plate (m/s)', &
      'back-face in-plane y strain at the gauge (-)', 'impactor kinetic energy (J)', &
      'plate kinetic energy (J)', 'plate strain energy (J)', &
      'work of the contact force on the plate (J)', &
      'int F d(alpha), contact energy (J)', 'energy balance error E0 - sum (J)', &
      'law branch 0 none 1 load 2 unload 3 reload (-)', 'contact iterations, eq. (17) (-)', &
      'plate solutions in the step (-)']

   !> One row of the history file, SI units (converted on output).
   type :: history_row_t
      real(dp) :: time = 0, force = 0, alpha = 0, w_plate = 0, w_impactor = 0
      real(dp) :: v_impactor = 0, strain_y = 0, ke_impactor = 0, ke_plate = 0
      real(dp) :: strain_energy = 0, contact_work = 0, indentation_energy = 0
      real(dp) :: energy_error = 0
      integer :: branch = 0, contact_iter = 0, nonlinear_iter = 0
   end type history_row_t

   !> The run's figures, gathered step by step.
   type :: run_summary_t
      real(dp) :: peak_force = 0.0_dp          !< N
      real(dp) :: time_of_peak = 0.0_dp        !< s
      real(dp) :: first_contact_start = -1.0_dp, first_contact_end = -1.0_dp  !< s
      integer :: contacts = 0                  !< separate contact intervals
      logical :: in_contact = .false.
      real(dp) :: max_deflection = 0.0_dp      !< m
      real(dp) :: max_strain_y = 0.0_dp        !< largest |strain_y_back|
      real(dp) :: max_energy_error = 0.0_dp    !< largest |energy error| (J)
      real(dp) :: permanent_indentation = 0.0_dp !< alpha_0 at the end (m)
      real(dp) :: final_velocity = 0.0_dp      !< impactor velocity at the end (m/s)
      real(dp) :: initial_energy = 0.0_dp      !< m v0^2 / 2 (J)
      integer :: steps = 0, plate_solves = 0, factorizations = 0
      integer :: contact_iterations = 0, max_contact_iter = 0, max_nonlinear_iter = 0
      integer :: unconverged_steps = 0         !< steps whose iterations did not converge (the run stops at the first)
      integer :: warnings = 0                  !< warnings given (each kind once)
      integer :: nonlinear_fallback_steps = 0  !< steps where eq. (19) needed its fall-back (Anderson mixing)
      integer :: contact_fallback_steps = 0    !< steps where the contact iteration needed its fall-back
      real(dp) :: max_w_over_h = 0.0_dp        !< largest plate deflection over the thickness
      real(dp) :: cpu_s = 0.0_dp
      character(len=64) :: status = 'completed'
   end type run_summary_t

contains

   !> Creates the directory of prefix if needed, opens <prefix>_history.dat
   !> and writes its header.
   subroutine open_history(deck, unit, path, stat, errmsg)
      type(deck_t), intent(in) :: deck              !< effective deck (echoed)
      integer, intent(out) :: unit                  !< unit of the open file
      character(len=*), intent(out) :: path         !< its path
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      character(len=msg_len) :: iomsg
      integer :: c

      call make_parent_directory(deck%prefix)
      path = trim(deck%prefix)//'_history.dat'
      open (newunit=unit, file=path, status='replace', action='write', iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         errmsg = '&output: prefix = "'//trim(deck%prefix)//'": cannot write '//trim(path)//': '//trim(iomsg)
         return
      end if
      write (unit, '(a)') '# impact: history of a low-velocity impact (Choi, Hong & Lee 1991)'
      call echo_deck(deck, unit, '# ')
      write (unit, '(a)') '# columns:'
      do c = 1, ncol
         write (unit, '(a,i2,1x,a20,1x,a)') '# ', c, col_name(c), trim(col_text(c))
      end do
      write (unit, '(a)', advance='no') '#'
      do c = 1, ncol
         write (unit, '(1x,a)', advance='no') trim(col_name(c))
      end do
      write (unit, '(a)') ''
      flush (unit)
   end subroutine open_history

   !> Writes one row (converted to the columns' units) and flushes it.
   subroutine write_history_row(unit, row)
      integer, intent(in) :: unit              !< history file
      type(history_row_t), intent(in) :: row   !< the row, SI units
      write (unit, '(f12.4, 12es16.7e3, 3i6)') row%time*1.0e6_dp, row%force, &
         row%alpha*1.0e3_dp, row%w_plate*1.0e3_dp, row%w_impactor*1.0e3_dp, &
         row%v_impactor, row%strain_y, row%ke_impactor, row%ke_plate, &
         row%strain_energy, row%contact_work, row%indentation_energy, row%energy_error, &
         row%branch, row%contact_iter, row%nonlinear_iter
      flush (unit)
   end subroutine write_history_row

   !> Updates the summary with the state at the end of a step.
   pure subroutine summary_record(s, time, force, w_plate, strain_y)
      type(run_summary_t), intent(inout) :: s   !< summary
      real(dp), intent(in) :: time              !< s
      real(dp), intent(in) :: force             !< N
      real(dp), intent(in) :: w_plate           !< m
      real(dp), intent(in) :: strain_y          !< -
      if (force > s%peak_force) then
         s%peak_force = force
         s%time_of_peak = time
      end if
      if (force > 0.0_dp .and. .not. s%in_contact) then
         s%in_contact = .true.
         s%contacts = s%contacts + 1
         if (s%contacts == 1) s%first_contact_start = time
      else if (force <= 0.0_dp .and. s%in_contact) then
         s%in_contact = .false.
         if (s%contacts == 1) s%first_contact_end = time
      end if
      s%max_deflection = max(s%max_deflection, abs(w_plate))
      s%max_strain_y = max(s%max_strain_y, abs(strain_y))
   end subroutine summary_record

   !> Writes <prefix>_summary.dat as 'key = value' lines, after the deck echo.
   subroutine write_summary(deck, s, stat, errmsg)
      type(deck_t), intent(in) :: deck            !< effective deck
      type(run_summary_t), intent(in) :: s        !< summary
      integer, intent(out) :: stat                !< 0 on success
      character(len=*), intent(inout) :: errmsg   !< reason on failure
      character(len=msg_len) :: iomsg, path
      real(dp) :: duration
      logical :: ended
      integer :: u

      path = trim(deck%prefix)//'_summary.dat'
      open (newunit=u, file=path, status='replace', action='write', iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         errmsg = '&output: cannot write '//trim(path)//': '//trim(iomsg)
         return
      end if
      ! first contact: its duration, or the time in contact so far if it has
      ! not ended by the last step (then first_contact_ended = false)
      duration = 0.0_dp
      ended = s%contacts == 0 .or. s%first_contact_end >= 0.0_dp
      if (s%contacts >= 1) then
         if (ended) then
            duration = s%first_contact_end - s%first_contact_start
         else
            duration = real(s%steps, dp)*deck%dt - s%first_contact_start
         end if
      end if
      write (u, '(a)') '# impact: summary (key = value; units in the key names)'
      call echo_deck(deck, u, '# ')
      write (u, '(a,a)')      'status = ', trim(s%status)
      write (u, '(a,es15.7)') 'peak_force_N = ', s%peak_force
      write (u, '(a,f12.4)')  'time_of_peak_us = ', s%time_of_peak*1.0e6_dp
      write (u, '(a,f12.4)')  'contact_duration_us = ', duration*1.0e6_dp
      write (u, '(a,a)')      'first_contact_ended = ', merge('true ', 'false', ended)
      write (u, '(a,i0)')     'contacts = ', s%contacts
      write (u, '(a,es15.7)') 'max_deflection_mm = ', s%max_deflection*1.0e3_dp
      write (u, '(a,es15.7)') 'max_strain_y_back = ', s%max_strain_y
      write (u, '(a,es15.7)') 'permanent_indentation_mm = ', s%permanent_indentation*1.0e3_dp
      write (u, '(a,es15.7)') 'rebound_velocity_m_s = ', -s%final_velocity
      write (u, '(a,es15.7)') 'initial_energy_J = ', s%initial_energy
      write (u, '(a,es15.7)') 'max_energy_error_J = ', s%max_energy_error
      write (u, '(a,i0)')     'steps = ', s%steps
      write (u, '(a,i0)')     'plate_solves = ', s%plate_solves
      write (u, '(a,i0)')     'factorizations = ', s%factorizations
      write (u, '(a,i0)')     'contact_iterations = ', s%contact_iterations
      write (u, '(a,i0)')     'max_contact_iter = ', s%max_contact_iter
      write (u, '(a,i0)')     'max_nonlinear_iter = ', s%max_nonlinear_iter
      write (u, '(a,i0)')     'unconverged_steps = ', s%unconverged_steps
      write (u, '(a,i0)')     'nonlinear_fallback_steps = ', s%nonlinear_fallback_steps
      write (u, '(a,i0)')     'contact_fallback_steps = ', s%contact_fallback_steps
      write (u, '(a,es15.7)') 'max_w_over_h = ', s%max_w_over_h
      write (u, '(a,i0)')     'warnings = ', s%warnings
      write (u, '(a,f12.4)')  'cpu_s = ', s%cpu_s
      close (u)
   end subroutine write_summary

   !> Before any work: creates the directory of prefix, refuses to replace
   !> the results of another run (<prefix>_history.dat, _summary.dat, .h5)
   !> unless deck%overwrite, and checks that <prefix>_history.dat can be
   !> written (an existing file is opened for appending and left as it is; a
   !> new one is created and deleted). Messages name the deck, &output and
   !> prefix.
   subroutine check_output(deck, stat, errmsg)
      type(deck_t), intent(in) :: deck              !< effective deck
      integer, intent(out) :: stat                  !< 0 when the run may write its results
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      character(len=msg_len) :: iomsg, head
      character(len=len(deck%prefix) + len(history_suffix)) :: path(3)
      integer :: u, i, nfile
      logical :: exists

      stat = 0
      head = trim(deck%source)//": &output: prefix = '"//trim(deck%prefix)//"': "
      call make_parent_directory(deck%prefix)
      path(1) = trim(deck%prefix)//history_suffix
      path(2) = trim(deck%prefix)//summary_suffix
      path(3) = trim(deck%prefix)//'.h5'
      nfile = merge(3, 2, deck%hdf5)
      results: do i = 1, nfile
         inquire (file=trim(path(i)), exist=exists)
         if (exists .and. .not. deck%overwrite) then
            stat = 1
            errmsg = trim(head)//' '//trim(path(i))//' exists, the results of another run: '// &
               'choose another prefix, or set overwrite = .true. in &output (or run impact --overwrite) '// &
               'to replace them'
            return
         end if
      end do results

      inquire (file=trim(path(1)), exist=exists)
      if (exists) then
         open (newunit=u, file=trim(path(1)), status='old', action='write', position='append', &
               iostat=stat, iomsg=iomsg)
         if (stat == 0) close (u, status='keep')
      else
         open (newunit=u, file=trim(path(1)), status='new', action='write', iostat=stat, iomsg=iomsg)
         if (stat == 0) close (u, status='delete')
      end if
      if (stat /= 0) errmsg = trim(head)//' cannot write '//trim(path(1))//': '//trim(iomsg)
   end subroutine check_output

   !> mkdir -p of the directory part of a path prefix (nothing if none).
   subroutine make_parent_directory(prefix)
      character(len=*), intent(in) :: prefix   !< output path prefix
      integer :: slash, ex
      slash = index(prefix, '/', back=.true.)
      if (slash > 1) then
         call execute_command_line('mkdir -p "'//prefix(1:slash-1)//'"', exitstat=ex)
      end if
   end subroutine make_parent_directory

end module output_files
