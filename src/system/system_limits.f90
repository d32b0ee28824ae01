!> What the machine offers a run, asked of the C library: memory (physical, free, the control
!> group's and the process's limits), a file system's free space, read-only mount and longest
!> name, the largest file the process may write. The deck's checks and the result files compare
!> a scene's needs against them before any work; a size is -1 when the system does not tell or
!> sets no limit (no check then). More: docs/ROBUSTNESS.md.
module system_limits
   use, intrinsic :: iso_c_binding, only: c_int, c_long, c_null_char
   use kinds, only: dp
   use file_system, only: nearest_directory
   use c_library, only: statvfs_t, rlimit_t, c_sysconf, c_statvfs, c_getrlimit
   implicit none
   private
   public :: physical_memory, memory_available, memory_room, free_disk_space, file_size_limit, read_only_file_system, name_max, &
      path_max

   !> sysconf names (Linux, <unistd.h>): _SC_PAGESIZE, _SC_PHYS_PAGES.
   integer(c_int), parameter :: sc_pagesize = 30, sc_phys_pages = 85
   !> getrlimit resources (Linux): RLIMIT_FSIZE, RLIMIT_DATA, RLIMIT_AS;
   !> RLIM_INFINITY reads as -1.
   integer(c_int), parameter :: rlimit_fsize = 1, rlimit_data = 2, rlimit_as = 9
   !> statvfs's f_flag of a file system mounted read-only (<sys/statvfs.h>).
   integer(c_long), parameter :: st_rdonly = 1
   !> The longest name when the file system does not tell (POSIX's NAME_MAX
   !> on Linux), and the longest path with its final NUL (PATH_MAX).
   integer, parameter :: default_name_max = 255, path_max = 4096

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

   !> The memory a run may take on this machine (bytes), -1 when nothing
   !> tells: the least of its physical memory, MemAvailable (/proc/meminfo)
   !> and the limit of the process's control group (cgroup v2 memory.max, v1
   !> memory.limit_in_bytes, of its group or the root a container sees).
   function memory_available() result(bytes)
      real(dp) :: bytes
      character(len=1024) :: line
      integer :: u, ios, c1, c2
      bytes = physical_memory()
      call take_file('/proc/meminfo', 'MemAvailable:', 1024.0_dp)
      call take_file('/sys/fs/cgroup/memory.max', '', 1.0_dp)
      call take_file('/sys/fs/cgroup/memory/memory.limit_in_bytes', '', 1.0_dp)
      open (newunit=u, file='/proc/self/cgroup', status='old', action='read', iostat=ios)
      if (ios /= 0) return
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         c1 = index(line, ':')
         c2 = c1 + index(line(c1 + 1:), ':')
         if (c1 == 0 .or. c2 == c1) cycle
         if (c2 == c1 + 1) &
            call take_file('/sys/fs/cgroup' // trim(line(c2 + 1:)) // '/memory.max', '', 1.0_dp)
         if (index(',' // line(c1 + 1:c2 - 1) // ',', ',memory,') > 0) call take_file( &
            '/sys/fs/cgroup/memory' // trim(line(c2 + 1:)) // '/memory.limit_in_bytes', '', 1.0_dp)
      end do
      close (u, iostat=ios)

   contains

      !> The number of `unit` bytes after `key` in the first line of the file
      !> `path` that starts with it (key '': the first line; 'max': none).
      subroutine take_file(path, key, unit)
         character(len=*), intent(in) :: path, key
         real(dp), intent(in) :: unit
         character(len=1024) :: text
         integer :: v, ios
         open (newunit=v, file=path, status='old', action='read', iostat=ios)
         if (ios /= 0) return          ! (v is undefined after a failed open: no close)
         do
            read (v, '(a)', iostat=ios) text
            if (ios /= 0) exit
            if (index(text, key) /= 1) cycle
            call take_text(text(len(key) + 1:), unit)
            exit
         end do
         close (v, iostat=ios)
      end subroutine take_file

      !> A number of `unit` bytes at the start of `text` (else nothing).
      subroutine take_text(text, unit)
         character(len=*), intent(in) :: text
         real(dp), intent(in) :: unit
         real(dp) :: x
         integer :: ios
         read (text, *, iostat=ios) x
         if (ios /= 0 .or. x <= 0.0_dp) return
         if (bytes < 0.0_dp .or. x*unit < bytes) bytes = x*unit
      end subroutine take_text

   end function memory_available

   !> The memory this process may still allocate (bytes), -1 when not limited:
   !> the smaller of RLIMIT_AS (ulimit -v) less its mapped space and
   !> RLIMIT_DATA (ulimit -d) less its data, both from /proc/self/statm (size,
   !> resident, shared, text, lib, data, in pages; 0 when unknown).
   function memory_room() result(bytes)
      real(dp) :: bytes
      real(dp) :: pages(6)
      integer(c_long) :: page
      integer :: u, ios
      bytes = -1.0_dp
      page = c_sysconf(sc_pagesize)
      open (newunit=u, file='/proc/self/statm', status='old', action='read', iostat=ios)
      if (ios == 0) then
         read (u, *, iostat=ios) pages
         close (u)
      end if
      if (ios /= 0 .or. page <= 0) pages = 0.0_dp
      call take(rlimit_as, pages(1)*real(page, dp))      ! VmSize
      call take(rlimit_data, pages(6)*real(page, dp))    ! VmData + VmStk

   contains

      !> bytes: the smaller of itself and the room under resource's limit.
      subroutine take(resource, used)
         integer(c_int), intent(in) :: resource    !< RLIMIT_AS or RLIMIT_DATA
         real(dp), intent(in) :: used              !< what counts against it now (bytes)
         type(rlimit_t) :: lim
         real(dp) :: room
         if (c_getrlimit(resource, lim) /= 0) return
         if (lim%rlim_cur <= 0) return             ! RLIM_INFINITY
         room = max(real(lim%rlim_cur, dp) - used, 0.0_dp)
         bytes = merge(room, min(bytes, room), bytes < 0.0_dp)
      end subroutine take

   end function memory_room

   !> The space free to an unprivileged user (bytes) on the file system that
   !> holds `path`, or would (its nearest existing parent directory); -1 when unknown.
   function free_disk_space(path) result(bytes)
      character(len=*), intent(in) :: path   !< a file or directory path, existing or not
      real(dp) :: bytes
      type(statvfs_t) :: buf
      bytes = -1.0_dp
      if (c_statvfs(nearest_directory(path) // c_null_char, buf) /= 0) return
      bytes = real(buf%f_bavail, dp)*real(buf%f_frsize, dp)
   end function free_disk_space

   !> True when the file system that holds `path` (or its nearest existing
   !> parent directory) is mounted read-only; false when it cannot be told.
   function read_only_file_system(path) result(read_only)
      character(len=*), intent(in) :: path   !< a file or directory path, existing or not
      logical :: read_only
      type(statvfs_t) :: buf
      read_only = .false.
      if (c_statvfs(nearest_directory(path) // c_null_char, buf) /= 0) return
      read_only = iand(buf%f_flag, st_rdonly) /= 0
   end function read_only_file_system

   !> The longest file name (bytes) the file system that holds `path` (or its nearest existing
   !> parent directory) takes: its f_namemax, 255 when it does not tell.
   function name_max(path) result(bytes)
      character(len=*), intent(in) :: path   !< a file or directory path, existing or not
      integer :: bytes
      type(statvfs_t) :: buf
      bytes = default_name_max
      if (c_statvfs(nearest_directory(path) // c_null_char, buf) /= 0) return
      if (buf%f_namemax > 0 .and. buf%f_namemax < huge(bytes)) bytes = int(buf%f_namemax)
   end function name_max

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
