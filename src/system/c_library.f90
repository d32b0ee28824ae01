!> The C library as the program calls it (ISO C binding), in one place: its
!> functions' interfaces and its structs, those of 64-bit Linux (glibc),
!> by header. What the calls mean is said where they are made (file_system,
!> system_limits, process_stop, child_process). Paths end in c_null_char.
module c_library
   use, intrinsic :: iso_c_binding, only: c_int, c_long, c_char, c_ptr, c_funptr, c_int64_t, c_size_t
   use, intrinsic :: iso_c_binding, only: c_int32_t, c_int16_t
   implicit none
   private
   public :: statvfs_t, rlimit_t, statx_t, c_statx
   public :: c_fopen, c_fclose, c_fileno, c_rename, c_lseek, c_truncate, c_sysconf, c_mkdir, c_flock, &
             c_statvfs, c_getrlimit, c_signal, c_exit, c_isatty
   public :: c_open, c_close, c_fsync, c_unlink, c_write
   public :: spawn_actions_t, cpu_set_t, c_posix_spawn, c_spawn_actions_init, &
             c_spawn_actions_destroy, c_spawn_actions_addopen, c_spawn_actions_adddup2, c_waitpid, &
             c_readlink, c_sched_getaffinity, o_write_no_follow
   public :: spawn_attr_t, c_spawnattr_init, c_spawnattr_destroy, c_spawnattr_setflags, c_spawnattr_setpgroup, &
             c_kill, c_getpid, c_getppid, c_prctl

   !> struct statvfs (<sys/statvfs.h>): eleven unsigned longs (read as
   !> signed: sizes below 2^63) and six ints.
   type, bind(c) :: statvfs_t
      integer(c_long) :: f_bsize, f_frsize, f_blocks, f_bfree, f_bavail, f_files, f_ffree, f_favail, &
                         f_fsid, f_flag, f_namemax
      integer(c_int) :: f_spare(6)
   end type statvfs_t

   !> struct rlimit (<sys/resource.h>): two rlim_t, unsigned long on Linux.
   type, bind(c) :: rlimit_t
      integer(c_long) :: rlim_cur, rlim_max
   end type rlimit_t

   !> posix_spawn_file_actions_t (<spawn.h>): opaque, 80 bytes in glibc; 128 reserved here.
   type, bind(c) :: spawn_actions_t
      integer(c_int64_t) :: opaque(16) = 0
   end type spawn_actions_t

   !> posix_spawnattr_t (<spawn.h>): opaque, 336 bytes in glibc; 512 reserved here.
   type, bind(c) :: spawn_attr_t
      integer(c_int64_t) :: opaque(64) = 0
   end type spawn_attr_t

   !> cpu_set_t (<sched.h>): a mask of 1024 CPUs, one bit each.
   type, bind(c) :: cpu_set_t
      integer(c_int64_t) :: bits(16) = 0
   end type cpu_set_t

   !> struct statx (<linux/stat.h>, Linux 4.11, glibc 2.28): the same layout on every
   !> architecture, unlike struct stat. The times are four struct statx_timestamp (a 64-bit
   !> second, a 32-bit nanosecond, 32 bits reserved), read here as pairs of 64-bit words.
   type, bind(c) :: statx_t
      integer(c_int32_t) :: stx_mask, stx_blksize
      integer(c_int64_t) :: stx_attributes
      integer(c_int32_t) :: stx_nlink, stx_uid, stx_gid
      integer(c_int16_t) :: stx_mode, stx_spare0     !< stx_mode: unsigned, read as signed
      integer(c_int64_t) :: stx_ino, stx_size, stx_blocks, stx_attributes_mask
      integer(c_int64_t) :: stx_times(8)
      integer(c_int32_t) :: stx_rdev_major, stx_rdev_minor, stx_dev_major, stx_dev_minor
      integer(c_int64_t) :: stx_spare2(14)
   end type statx_t

   !> open(2) flags (Linux, <fcntl.h>): write only, create, truncate, no symbolic link (open
   !> fails on one); the four together: a file written anew, never through a link.
   integer(c_int), parameter :: o_wronly = 1, o_creat = int(o'100', c_int), o_trunc = int(o'1000', c_int), &
                                o_nofollow = int(o'400000', c_int)
   integer(c_int), parameter :: o_write_no_follow = ior(o_wronly, ior(o_creat, ior(o_trunc, o_nofollow)))

   interface
      ! <stdio.h>
      type(c_ptr) function c_fopen(path, mode) bind(c, name='fopen')
         import :: c_char, c_ptr
         character(kind=c_char), intent(in) :: path(*), mode(*)
      end function c_fopen
      integer(c_int) function c_fclose(stream) bind(c, name='fclose')
         import :: c_ptr, c_int
         type(c_ptr), value :: stream
      end function c_fclose
      integer(c_int) function c_fileno(stream) bind(c, name='fileno')
         import :: c_ptr, c_int
         type(c_ptr), value :: stream
      end function c_fileno
      integer(c_int) function c_rename(old, new) bind(c, name='rename')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: old(*), new(*)
      end function c_rename
      ! <unistd.h> (off_t: 64 bits)
      integer(c_int64_t) function c_lseek(fd, offset, whence) bind(c, name='lseek')
         import :: c_int, c_int64_t
         integer(c_int), value :: fd, whence
         integer(c_int64_t), value :: offset
      end function c_lseek
      integer(c_int) function c_truncate(path, length) bind(c, name='truncate')
         import :: c_int, c_char, c_int64_t
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int64_t), value :: length
      end function c_truncate
      integer(c_long) function c_sysconf(name) bind(c, name='sysconf')
         import :: c_int, c_long
         integer(c_int), value :: name
      end function c_sysconf
      ! <sys/stat.h>
      integer(c_int) function c_mkdir(path, mode) bind(c, name='mkdir')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), value :: mode
      end function c_mkdir
      ! <sys/file.h>
      integer(c_int) function c_flock(fd, operation) bind(c, name='flock')
         import :: c_int
         integer(c_int), value :: fd, operation
      end function c_flock
      ! <sys/statvfs.h>
      integer(c_int) function c_statvfs(path, buf) bind(c, name='statvfs')
         import :: c_int, c_char, statvfs_t
         character(kind=c_char), intent(in) :: path(*)
         type(statvfs_t), intent(out) :: buf
      end function c_statvfs
      ! <sys/resource.h>
      integer(c_int) function c_getrlimit(resource, rlim) bind(c, name='getrlimit')
         import :: c_int, rlimit_t
         integer(c_int), value :: resource
         type(rlimit_t), intent(out) :: rlim
      end function c_getrlimit
      ! <signal.h>
      type(c_funptr) function c_signal(signum, handler) bind(c, name='signal')
         import :: c_int, c_funptr
         integer(c_int), value :: signum
         type(c_funptr), value :: handler
      end function c_signal
      ! <unistd.h>
      subroutine c_exit(status) bind(c, name='_exit')
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_exit
      integer(c_int) function c_isatty(fd) bind(c, name='isatty')
         import :: c_int
         integer(c_int), value :: fd
      end function c_isatty
      ! <fcntl.h>, <unistd.h>: the raw file calls, async-signal-safe (a signal
      ! handler may make them: src/system/process_stop.f90)
      integer(c_int) function c_open(path, flags) bind(c, name='open')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), value :: flags          ! no O_CREAT: no third argument
      end function c_open
      integer(c_int) function c_close(fd) bind(c, name='close')
         import :: c_int
         integer(c_int), value :: fd
      end function c_close
      integer(c_int) function c_fsync(fd) bind(c, name='fsync')
         import :: c_int
         integer(c_int), value :: fd
      end function c_fsync
      integer(c_int) function c_unlink(path) bind(c, name='unlink')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
      end function c_unlink
      integer(c_long) function c_write(fd, buf, count) bind(c, name='write')  ! ssize_t
         import :: c_int, c_char, c_size_t, c_long
         integer(c_int), value :: fd
         character(kind=c_char), intent(in) :: buf(*)
         integer(c_size_t), value :: count
      end function c_write
      ! <sys/stat.h> (glibc 2.28)
      integer(c_int) function c_statx(dirfd, path, flags, mask, buf) bind(c, name='statx')
         import :: c_int, c_char, statx_t
         integer(c_int), value :: dirfd, flags, mask
         character(kind=c_char), intent(in) :: path(*)
         type(statx_t), intent(out) :: buf
      end function c_statx
      integer(c_long) function c_readlink(path, buf, bufsiz) bind(c, name='readlink')  ! ssize_t
         import :: c_char, c_size_t, c_long
         character(kind=c_char), intent(in) :: path(*)
         character(kind=c_char), intent(out) :: buf(*)
         integer(c_size_t), value :: bufsiz
      end function c_readlink
      ! <spawn.h>
      integer(c_int) function c_posix_spawn(pid, path, actions, attr, argv, envp) &
            bind(c, name='posix_spawn')
         import :: c_int, c_char, c_ptr, spawn_actions_t, spawn_attr_t
         integer(c_int), intent(out) :: pid
         character(kind=c_char), intent(in) :: path(*)
         type(spawn_actions_t), intent(in) :: actions
         type(spawn_attr_t), intent(in) :: attr
         type(c_ptr), intent(in) :: argv(*), envp(*)
      end function c_posix_spawn
      integer(c_int) function c_spawn_actions_init(actions) &
            bind(c, name='posix_spawn_file_actions_init')
         import :: c_int, spawn_actions_t
         type(spawn_actions_t), intent(inout) :: actions
      end function c_spawn_actions_init
      integer(c_int) function c_spawn_actions_destroy(actions) &
            bind(c, name='posix_spawn_file_actions_destroy')
         import :: c_int, spawn_actions_t
         type(spawn_actions_t), intent(inout) :: actions
      end function c_spawn_actions_destroy
      integer(c_int) function c_spawn_actions_addopen(actions, fd, path, oflag, mode) &
            bind(c, name='posix_spawn_file_actions_addopen')
         import :: c_int, c_char, spawn_actions_t
         type(spawn_actions_t), intent(inout) :: actions
         integer(c_int), value :: fd, oflag, mode
         character(kind=c_char), intent(in) :: path(*)
      end function c_spawn_actions_addopen
      integer(c_int) function c_spawn_actions_adddup2(actions, fd, newfd) &
            bind(c, name='posix_spawn_file_actions_adddup2')
         import :: c_int, spawn_actions_t
         type(spawn_actions_t), intent(inout) :: actions
         integer(c_int), value :: fd, newfd
      end function c_spawn_actions_adddup2
      ! <sys/wait.h>
      integer(c_int) function c_waitpid(pid, status, options) bind(c, name='waitpid')
         import :: c_int
         integer(c_int), value :: pid, options
         integer(c_int), intent(out) :: status
      end function c_waitpid
      integer(c_int) function c_spawnattr_init(attr) bind(c, name='posix_spawnattr_init')
         import :: c_int, spawn_attr_t
         type(spawn_attr_t), intent(inout) :: attr
      end function c_spawnattr_init
      integer(c_int) function c_spawnattr_destroy(attr) bind(c, name='posix_spawnattr_destroy')
         import :: c_int, spawn_attr_t
         type(spawn_attr_t), intent(inout) :: attr
      end function c_spawnattr_destroy
      integer(c_int) function c_spawnattr_setflags(attr, flags) &
            bind(c, name='posix_spawnattr_setflags')
         import :: c_int, c_int16_t, spawn_attr_t
         type(spawn_attr_t), intent(inout) :: attr
         integer(c_int16_t), value :: flags
      end function c_spawnattr_setflags
      integer(c_int) function c_spawnattr_setpgroup(attr, pgroup) &
            bind(c, name='posix_spawnattr_setpgroup')
         import :: c_int, spawn_attr_t
         type(spawn_attr_t), intent(inout) :: attr
         integer(c_int), value :: pgroup
      end function c_spawnattr_setpgroup
      ! <signal.h> (kill: async-signal-safe), <unistd.h>, <sys/prctl.h>
      integer(c_int) function c_kill(pid, sig) bind(c, name='kill')
         import :: c_int
         integer(c_int), value :: pid, sig
      end function c_kill
      integer(c_int) function c_getpid() bind(c, name='getpid')
         import :: c_int
      end function c_getpid
      integer(c_int) function c_getppid() bind(c, name='getppid')
         import :: c_int
      end function c_getppid
      integer(c_int) function c_prctl(option, arg2) bind(c, name='prctl')
         import :: c_int, c_long
         integer(c_int), value :: option
         integer(c_long), value :: arg2      ! the options used take one argument
      end function c_prctl
      ! <sched.h>
      integer(c_int) function c_sched_getaffinity(pid, size, mask) bind(c, name='sched_getaffinity')
         import :: c_int, c_size_t, cpu_set_t
         integer(c_int), value :: pid
         integer(c_size_t), value :: size
         type(cpu_set_t), intent(out) :: mask
      end function c_sched_getaffinity
   end interface

end module c_library
