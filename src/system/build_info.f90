!> What built this program, written at build time into
!> build/code_version.inc by mk/hdf5.mk:
!>   code_release  the release number, the file VERSION's ('1.2.0');
!>   code_version  'impact <release> (git <commit>[-dirty])' when built in a
!>                 git checkout, 'impact <release>' otherwise (a source
!>                 archive); printed by `impact --version` and written into
!>                 every results file.
module build_info
   implicit none
   private
   public :: code_release, code_version

   include 'code_version.inc'
end module build_info
