!> How the process stops: on a stop signal (SIGTERM, SIGINT, SIGHUP, SIGUSR1, SIGUSR2) at once
!> in the set-up (the claimed result files removed, exit status 128 + N, async-signal-safe
!> calls only) and after the step in the run (the loop asks stop_signal_caught, the run ends
!> with its results and a restart point); or with an exit status (exit_program, _exit(2)). The
!> phase and the signal are module state: a handler can reach nothing else. Not from the paper.
!> More: docs/ROBUSTNESS.md.
module process_stop
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_funptr, c_funloc, c_intptr_t, c_size_t, c_long, &
      c_int64_t, c_null_char
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use c_library, only: c_signal, c_exit, c_open, c_close, c_lseek, c_unlink, c_write
   implicit none
   private
   public :: catch_stop_signals, remove_on_stop, stop_after_step, stop_signal_caught, keep_file_size_errors, &
             exit_program, stop_signals

   !> The stop signals, by their numbers on Linux (<signal.h>): SIGHUP,
   !> SIGINT, SIGUSR1, SIGUSR2, SIGTERM.
   integer(c_int), parameter :: stop_signals(5) = [1_c_int, 2_c_int, 10_c_int, 12_c_int, 15_c_int]
   !> SIGXFSZ (Linux, <signal.h>) and SIG_IGN, the handler that ignores a signal.
   integer(c_int), parameter :: sigxfsz = 25
   integer(c_intptr_t), parameter :: sig_ign = 1
   !> The phases (module header): a signal ends the set-up at once; it
   !> ends the run after its step.
   integer(c_int), parameter :: at_once = 0, after_step = 1
   !> open(2)'s O_RDONLY, lseek(2)'s SEEK_END, standard error's descriptor.
   integer(c_int), parameter :: o_rdonly = 0, seek_end = 2, stderr_fd = 2
   !> Files the set-up may leave (claimed, empty) and the longest path held.
   integer, parameter :: max_files = 4, max_path = 4096
   !> The set-up's last words, before and after the signal's number.
   character(len=*), parameter :: words_before = 'impact: stopped by signal ', &
      words_after = ' during set-up: no results written' // achar(10)

   !> The phase, and the signal caught so far in the run (0: none); set by
   !> on_signal and stop_after_step only.
   integer(c_int), volatile, save :: phase = at_once
   integer(c_int), volatile, save :: caught = 0_c_int
   !> The files to remove when a signal ends the set-up while they are
   !> empty: C strings, null-terminated.
   integer, save :: nfiles = 0
   character(kind=c_char), save :: files(max_path + 1, max_files) = c_null_char

contains

   !> From now on a stop signal (module header) ends the set-up at once; to be called first.
   subroutine catch_stop_signals()
      type(c_funptr) :: previous
      integer :: k
      phase = at_once
      caught = 0_c_int
      do k = 1, size(stop_signals)
         previous = c_signal(stop_signals(k), c_funloc(on_signal))
      end do
   end subroutine catch_stop_signals

   !> The file `path`, which the run created empty (its claim), is removed
   !> when a stop signal ends the set-up and it is still empty; ignored
   !> beyond max_files files or max_path characters (then it stays).
   subroutine remove_on_stop(path)
      character(len=*), intent(in) :: path   !< the file
      if (nfiles == max_files .or. len(path) > max_path) return
      files(:len(path), nfiles + 1) = transfer(path, files(:, 1), len(path))
      files(len(path) + 1, nfiles + 1) = c_null_char
      nfiles = nfiles + 1
   end subroutine remove_on_stop

   !> From now on a stop signal is recorded and ends the run after its step
   !> (stop_signal_caught); to be called before the first result is written.
   subroutine stop_after_step()
      phase = after_step
   end subroutine stop_after_step

   !> The number of the stop signal received during the run so far, 0 if none.
   integer function stop_signal_caught() result(signum)
      signum = int(caught)
   end function stop_signal_caught

   !> The handler (module header): in the run it records the signal; in the
   !> set-up it removes the empty claimed files, says so and ends the process.
   subroutine on_signal(signum) bind(c)
      integer(c_int), value :: signum   !< the signal received
      integer(c_int) :: fd, r
      integer(c_int64_t) :: bytes
      integer(c_long) :: written
      character(kind=c_char) :: digits(2)
      integer :: k, n
      if (phase == after_step) then
         caught = signum
         return
      end if
      do k = 1, nfiles
         fd = c_open(files(:, k), o_rdonly)
         if (fd < 0) cycle
         bytes = c_lseek(fd, 0_c_int64_t, seek_end)
         r = c_close(fd)
         if (bytes == 0) r = c_unlink(files(:, k))
      end do
      digits = [achar(48 + signum/10), achar(48 + mod(signum, 10))]
      n = merge(2, 1, signum >= 10)                ! the signal's number has one or two digits
      written = c_write(stderr_fd, words_before, len(words_before, c_size_t))
      written = c_write(stderr_fd, digits(3 - n:), int(n, c_size_t))
      written = c_write(stderr_fd, words_after, len(words_after, c_size_t))
      call c_exit(128 + signum)
   end subroutine on_signal

   !> From now on a write past the file-size limit fails (EFBIG) instead of
   !> raising SIGXFSZ (module header).
   subroutine keep_file_size_errors()
      type(c_funptr) :: previous
      previous = c_signal(sigxfsz, transfer(sig_ign, previous))
   end subroutine keep_file_size_errors

   !> Ends the program with exit status `code`, silently and at once (its
   !> files closed by the caller).
   subroutine exit_program(code)
      integer, intent(in) :: code   !< the process's exit status (0: success)
      flush (output_unit)
      flush (error_unit)
      call c_exit(int(code, c_int))
   end subroutine exit_program

end module process_stop
