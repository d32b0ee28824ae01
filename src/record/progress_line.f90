!> The run's progress on standard error: the step, the simulated time, the
!> percentage and the time left (wall time per step, timed from the end of
!> the first, times the steps left). On a terminal one line rewritten in
!> place; otherwise a plain line now and then. Not from the paper. More: README.md.
module progress_line
   use, intrinsic :: iso_fortran_env, only: error_unit, int64
   use kinds, only: dp
   use c_library, only: c_isatty
   use number_text, only: int_str
   implicit none
   private
   public :: progress_t, progress_start, progress_step, progress_end, progress_due, progress_timed, progress_left, &
             duration_text

   !> Updates a second, at most, of the line on a terminal.
   real(dp), parameter :: terminal_rate = 4.0_dp
   !> Seconds between two plain lines when standard error is not a terminal.
   real(dp), parameter :: log_interval = 30.0_dp
   !> Steps timed, after the first, before the time left is estimated.
   integer, parameter, public :: timed_steps = 5

   !> Where the run's progress stands.
   type :: progress_t
      logical :: terminal = .false.        !< standard error is a terminal: one line, rewritten
      integer :: nstep = 0                 !< the run's steps
      real(dp) :: t_end = 0                !< its end time (s)
      real(dp) :: interval = log_interval  !< wall seconds between two updates
      integer(int64) :: count0 = 0         !< system_clock at the first step
      integer(int64) :: rate = 1           !< system_clock's counts per second
      real(dp) :: last = 0                 !< wall seconds since count0 at the last update
      integer :: step0 = -1                !< the step the timing starts after (-1: none recorded yet)
      real(dp) :: elapsed0 = 0             !< wall seconds since count0 at its end
      logical :: shown = .false.           !< a line is on the terminal, to be cleared
   end type progress_t

contains

   !> The clock starts: the run has nstep steps to t_end.
   subroutine progress_start(prog, nstep, t_end)
      type(progress_t), intent(out) :: prog   !< the progress
      integer, intent(in) :: nstep            !< the run's steps
      real(dp), intent(in) :: t_end           !< its end time (s)
      prog%terminal = c_isatty(2) == 1
      prog%interval = merge(1.0_dp/terminal_rate, log_interval, prog%terminal)
      prog%nstep = nstep
      prog%t_end = t_end
      call system_clock(prog%count0, prog%rate)
   end subroutine progress_start

   !> After step `step`, at the simulated time t: the line, when it is due.
   subroutine progress_step(prog, step, t)
      type(progress_t), intent(inout) :: prog   !< the progress
      integer, intent(in) :: step               !< the step just recorded
      real(dp), intent(in) :: t                 !< its time (s)
      integer(int64) :: now
      real(dp) :: elapsed
      if (prog%nstep <= 0) return
      call system_clock(now)
      elapsed = real(now - prog%count0, dp)/real(prog%rate, dp)
      call progress_timed(prog, step, elapsed)
      if (.not. progress_due(prog%last, elapsed, prog%interval)) return
      prog%last = elapsed
      if (prog%terminal) then
         write (error_unit, '(a)', advance='no') achar(13) // progress_text(prog, step, t, elapsed) // '   '
         prog%shown = .true.
      else
         write (error_unit, '(a)') progress_text(prog, step, t, elapsed)
      end if
      flush (error_unit)
   end subroutine progress_step

   !> The run has ended: the terminal's line is cleared.
   subroutine progress_end(prog)
      type(progress_t), intent(inout) :: prog   !< the progress
      if (.not. prog%shown) return
      write (error_unit, '(a)', advance='no') achar(13) // repeat(' ', 79) // achar(13)
      flush (error_unit)
      prog%shown = .false.
   end subroutine progress_end

   !> Whether an update is due at `elapsed` seconds, the last one at `last` (0: none).
   pure logical function progress_due(last, elapsed, interval) result(due)
      real(dp), intent(in) :: last       !< wall seconds at the last update
      real(dp), intent(in) :: elapsed    !< wall seconds now
      real(dp), intent(in) :: interval   !< wall seconds between updates
      due = elapsed - last >= interval
   end function progress_due

   !> The steps are timed from the end of the first (it may cost far more).
   pure subroutine progress_timed(prog, step, elapsed)
      type(progress_t), intent(inout) :: prog   !< the progress
      integer, intent(in) :: step               !< the step just recorded
      real(dp), intent(in) :: elapsed           !< wall seconds since the clock started
      if (prog%step0 >= 0) return
      prog%step0 = step
      prog%elapsed0 = elapsed
   end subroutine progress_timed

   !> The wall time left (s) after `step`; -1 until `timed_steps` steps are timed.
   pure real(dp) function progress_left(prog, step, elapsed) result(left)
      type(progress_t), intent(in) :: prog   !< the progress
      integer, intent(in) :: step            !< the step just recorded
      real(dp), intent(in) :: elapsed        !< wall seconds since the clock started
      left = -1.0_dp
      if (prog%step0 < 0 .or. step - prog%step0 < timed_steps) return
      ! the time per step of those timed, times the steps left
      left = (elapsed - prog%elapsed0)*real(prog%nstep - step, dp)/real(step - prog%step0, dp)
   end function progress_left

   !> A wall time for people: '42 s', '3 min 05 s', '2 h 07 min'.
   pure function duration_text(seconds) result(text)
      real(dp), intent(in) :: seconds   !< the time (s)
      character(len=:), allocatable :: text
      integer :: s
      character(len=2) :: two
      s = nint(max(seconds, 0.0_dp))
      if (s < 60) then
         text = int_str(s) // ' s'
      else if (s < 3600) then
         write (two, '(i2.2)') mod(s, 60)
         text = int_str(s/60) // ' min ' // two // ' s'
      else
         write (two, '(i2.2)') mod(s/60, 60)
         text = int_str(s/3600) // ' h ' // two // ' min'
      end if
   end function duration_text

   !> The progress line: 'impact: step 480/1200 (t = 1.200 ms of 3.000 ms), 40 %, 12 s left'.
   function progress_text(prog, step, t, elapsed) result(text)
      type(progress_t), intent(in) :: prog   !< the progress
      integer, intent(in) :: step            !< the step
      real(dp), intent(in) :: t              !< its time (s)
      real(dp), intent(in) :: elapsed        !< wall seconds since the first step
      character(len=:), allocatable :: text
      character(len=16) :: ms(2)                         ! t and t_end (ms)
      write (ms, '(f16.3)') t*1.0e3_dp, prog%t_end*1.0e3_dp
      text = 'impact: step ' // int_str(step) // '/' // int_str(prog%nstep) // ' (t = ' &
         // trim(adjustl(ms(1))) // ' ms of ' // trim(adjustl(ms(2))) // ' ms), ' &
         // int_str(int(100.0_dp*real(step, dp)/real(prog%nstep, dp))) // ' %'
      if (progress_left(prog, step, elapsed) >= 0.0_dp) &
         text = text // ', ' // duration_text(progress_left(prog, step, elapsed)) // ' left'
   end function progress_text

end module progress_line
