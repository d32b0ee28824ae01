!> How the process stops: after the step on a stop signal, or at once with
!> an exit status.
!>
!> Stop signals. A run that is asked to stop (SIGTERM: a batch system's time limit, e.g.
!> Slurm's; SIGINT: Ctrl-C) ends at the end of the step it is in, with its
!> results written and the summary saying so (src/impact.f90), instead
!> of dying mid-write.
!>
!> catch_stop_signals installs a handler for both through the C library's
!> signal(); the handler only records the signal's number (an assignment is
!> all a handler may safely do) and stays installed: the same signal often
!> comes twice (timeout(1) sends it to the program and to its process
!> group; Slurm to every process of the job), and the second must not kill
!> the run while it writes its results. The time loop (src/impact.f90) asks
!> stop_signal_caught() after every step (SIGKILL or SIGQUIT still end a
!> step that hangs).
!>
!> keep_file_size_errors ignores SIGXFSZ: a write past the process's
!> file-size limit (ulimit -f) then fails with EFBIG, which the writer
!> reports (src/results/run_recorder.f90), instead of killing the process with its
!> files half written.
!>
!> Module state, the one exception in this code to "no saved hidden state":
!> the number of the signal caught. A signal
!> handler receives nothing but the signal's number and can reach nothing
!> but global data, so the flag must live here; it is volatile because it
!> changes outside the normal flow of the program.
!>
!> The exit status. Fortran 2008's `error stop 1` prints "ERROR STOP 1" after the program's
!> own message, and gfortran adds a note on the floating-point flags; a
!> failed run must say one line (docs/ROBUSTNESS.md, "Stability, bad input, nothing
!> lost"). exit_program flushes standard output and error and ends the
!> process at once, through the C library's _exit(2): no exit handler runs,
!> in particular not HDF5's, which would try to close a results file a
!> failed write left behind and rewrite its metadata for data that is not
!> there (src/results/results_hdf5.f90), or crash in the attempt. So the caller
!> closes its own files first; every path of src/impact.f90 does.
module process_stop
   use, intrinsic :: iso_c_binding, only: c_int, c_funptr, c_funloc, c_intptr_t
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use c_library, only: c_signal, c_exit
   implicit none
   private
   public :: catch_stop_signals, stop_signal_caught, keep_file_size_errors, exit_program

   !> The signals caught, by their POSIX numbers (the same on Linux, the BSDs
   !> and macOS).
   integer, parameter :: sigint = 2, sigterm = 15
   !> SIGXFSZ (Linux, <signal.h>) and SIG_IGN, the handler that ignores a signal.
   integer(c_int), parameter :: sigxfsz = 25
   integer(c_intptr_t), parameter :: sig_ign = 1

   !> The signal caught so far (0: none). Set by on_signal only.
   integer(c_int), volatile, save :: caught = 0_c_int

contains

   !> From now on SIGINT and SIGTERM are recorded instead of ending the
   !> program.
   subroutine catch_stop_signals()
      type(c_funptr) :: previous
      caught = 0_c_int
      previous = c_signal(int(sigint, c_int), c_funloc(on_signal))
      previous = c_signal(int(sigterm, c_int), c_funloc(on_signal))
   end subroutine catch_stop_signals

   !> The number of the stop signal received so far, 0 if none.
   integer function stop_signal_caught() result(signum)
      signum = int(caught)
   end function stop_signal_caught

   !> The handler: records the signal, nothing else.
   subroutine on_signal(signum) bind(c)
      integer(c_int), value :: signum   !< the signal received
      caught = signum
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
