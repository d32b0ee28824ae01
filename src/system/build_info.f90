!> What built this program: code_version, 'impact <git describe>' at build
!> time (build/code_version.inc, written by mk/hdf5.mk), printed by
!> `impact --version` and written into every results file.
module build_info
   implicit none
   private
   public :: code_version

   include 'code_version.inc'
end module build_info
