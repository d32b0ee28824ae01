!> How the program ends with a status, and nothing else on the terminal.
!>
!> Fortran 2008's `error stop 1` prints "ERROR STOP 1" after the program's
!> own message, and gfortran adds a note on the floating-point flags; a
!> failed run must say one line (README, "Stability, bad input, nothing
!> lost"). exit_program flushes standard output and error and ends the
!> process at once, through the C library's _exit(2): no exit handler runs,
!> in particular not HDF5's, which would try to close a results file a
!> failed write left behind and rewrite its metadata for data that is not
!> there (src/results/results_hdf5.f90), or crash in the attempt. So the caller
!> closes its own files first; every path of src/impact.f90 does.
module program_exit
   use, intrinsic :: iso_c_binding, only: c_int
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   implicit none
   private
   public :: exit_program

   interface
      !> void _exit(int status)
      subroutine c_exit(status) bind(c, name='_exit')
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_exit
   end interface

contains

   !> Ends the program with exit status `code`, silently and at once (its
   !> files closed by the caller).
   subroutine exit_program(code)
      integer, intent(in) :: code   !< the process's exit status (0: success)
      flush (output_unit)
      flush (error_unit)
      call c_exit(int(code, c_int))
   end subroutine exit_program

end module program_exit
