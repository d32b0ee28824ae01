!> What the machine offers a run, asked of the C library (ISO C binding,
!> src/system/c_library.f90):
!> the physical memory (sysconf(3)), the free space of the file system a
!> path is on (statvfs(3)) and the largest file the process may write
!> (getrlimit(2), RLIMIT_FSIZE). The deck's checks compare what a scene would
!> need against them before any work (src/deck/input_deck.f90, docs/ROBUSTNESS.md,
!> "Stability, bad input, nothing lost"). Either answer is -1 when the
!> system does not tell, or sets no limit; the check is then skipped.
module system_limits
   use, intrinsic :: iso_c_binding, only: c_int, c_long, c_null_char
   use kinds, only: dp
   use file_system, only: parent_directory
   use c_library, only: statvfs_t, rlimit_t, c_sysconf, c_statvfs, c_getrlimit
   implicit none
   private
   public :: physical_memory, free_disk_space, file_size_limit

   !> sysconf names (Linux, <unistd.h>): _SC_PAGESIZE, _SC_PHYS_PAGES.
   integer(c_int), parameter :: sc_pagesize = 30, sc_phys_pages = 85
   !> getrlimit resource RLIMIT_FSIZE (Linux); RLIM_INFINITY reads as -1.
   integer(c_int), parameter :: rlimit_fsize = 1

contains

   !> The machine's physical memory (bytes), -1 when unknown.
   function physical_memory() result(bytes)
      real(dp) :: bytes
      integer(c_long) :: pages, page
      pages = c_sysconf(sc_phys_pages)
      page = c_sysconf(sc_pagesize)
      bytes = -1.0_dp
      if (pages > 0 .and. page > 0) bytes = real(pages, dp)*real(page, dp)
   end function physical_memory

   !> The space free to an unprivileged user (bytes) on the file system that
   !> holds `path`, or its nearest existing parent directory; -1 when unknown.
   function free_disk_space(path) result(bytes)
      character(len=*), intent(in) :: path   !< a file or directory path, existing or not
      real(dp) :: bytes
      type(statvfs_t) :: buf
      character(len=:), allocatable :: dir
      logical :: exists
      bytes = -1.0_dp
      dir = path
      nearest: do
         dir = parent_directory(dir)
         if (len(dir) == 0) then
            dir = '.'
            if (path(1:min(1, len(path))) == '/') dir = '/'
            exit nearest
         end if
         inquire (file=dir // '/.', exist=exists)
         if (exists) exit nearest
      end do nearest
      if (c_statvfs(dir // c_null_char, buf) /= 0) return
      bytes = real(buf%f_bavail, dp)*real(buf%f_frsize, dp)
   end function free_disk_space

   !> The largest file this process may write (bytes; ulimit -f), -1 when
   !> there is no limit or it is unknown.
   function file_size_limit() result(bytes)
      real(dp) :: bytes
      type(rlimit_t) :: lim
      bytes = -1.0_dp
      if (c_getrlimit(rlimit_fsize, lim) /= 0) return
      if (lim%rlim_cur > 0) bytes = real(lim%rlim_cur, dp)
   end function file_size_limit

end module system_limits
