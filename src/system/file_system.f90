!> What the program asks of the file system, through the C library (ISO C
!> binding, src/system/c_library.f90), never through a shell: a path is only ever a name here, so
!> nothing in it is interpreted.
!>
!>  - make_directories: `mkdir -p` of a path's directories, by mkdir(2);
!>  - path_problem: a path the program refuses to use (empty, control
!>    characters);
!>  - lock_file / unlock_file: an exclusive advisory lock (flock(2)) on a
!>    file, held until unlocked or the process ends (the kernel releases it
!>    then, even after a kill), so that two runs never write one file;
!>  - rename_file: rename(2), which replaces a file by another in one step;
!>  - truncate_file: truncate(2), which cuts a file to a length (a row
!>    half written when the disk filled up);
!>  - file_size, and file_probe_t (open_probe, probe_size, close_probe) to
!>    read it often: the length of a file as it is on disk, whatever a
!>    Fortran unit still holds in its buffer (gfortran 12 reports neither a
!>    failed write(2) under FLUSH nor the size on disk through INQUIRE on
!>    the unit); a probe keeps the file open, so one reading is one lseek(2).
module file_system
   use, intrinsic :: iso_c_binding, only: c_int, c_null_char, c_ptr, c_null_ptr, c_associated, c_int64_t
   use, intrinsic :: iso_fortran_env, only: int64
   use c_library, only: c_mkdir, c_fopen, c_lseek, c_fclose, c_fileno, c_rename, c_truncate, c_flock
   implicit none
   private
   public :: make_directories, parent_directory, path_problem
   public :: file_lock_t, lock_file, unlock_file, rename_file, truncate_file, file_size
   public :: file_probe_t, open_probe, probe_size, close_probe

   !> A lock taken by lock_file: the stream it holds open.
   type :: file_lock_t
      type(c_ptr) :: stream = c_null_ptr
   end type file_lock_t

   !> A file kept open for reading its length (open_probe): its stream.
   type :: file_probe_t
      type(c_ptr) :: stream = c_null_ptr
   end type file_probe_t

   !> lseek's whence SEEK_END: from the end of the file (<unistd.h>).
   integer(c_int), parameter :: seek_end = 2
   !> flock(2) operations (Linux, <sys/file.h>): exclusive, do not wait.
   integer(c_int), parameter :: lock_ex = 2, lock_nb = 4

   !> Permissions of a directory created here, before the umask: rwxrwxrwx.
   integer(c_int), parameter :: dir_mode = int(o'777', c_int)

contains

   !> The directory part of a path ('out' of 'out/clamped'), '' when none.
   pure function parent_directory(path) result(dir)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: dir
      integer :: slash
      slash = index(path, '/', back=.true.)
      dir = ''
      if (slash > 1) dir = path(:slash - 1)
   end function parent_directory

   !> Creates the directory dir and every missing one above it, like
   !> `mkdir -p`; existing directories are fine. stat /= 0 when one cannot
   !> be made (a file in the way, no permission), with the directory named.
   subroutine make_directories(dir, stat, errmsg)
      character(len=*), intent(in) :: dir           !< the directory
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< the directory that could not be made
      integer :: k
      integer(c_int) :: r
      logical :: exists
      stat = 0
      if (len_trim(dir) == 0) return
      ! every prefix ending before a '/', then the whole path
      do k = 2, len_trim(dir) + 1
         if (k <= len_trim(dir)) then
            if (dir(k:k) /= '/') cycle
         end if
         inquire (file=dir(:k - 1) // '/.', exist=exists)
         if (exists) cycle
         r = c_mkdir(dir(:k - 1) // c_null_char, dir_mode)
         inquire (file=dir(:k - 1) // '/.', exist=exists)
         if (.not. exists) then
            stat = 1
            errmsg = 'cannot create the directory ''' // dir(:k - 1) // ''''
            return
         end if
      end do
   end subroutine make_directories

   !> Why a path cannot be used, '' when it can: empty, or holding a control
   !> character (a newline or an escape in a file name is never meant).
   pure function path_problem(path) result(why)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: why
      integer :: k
      why = ''
      if (len_trim(path) == 0) then
         why = 'must not be empty'
         return
      end if
      do k = 1, len(path)
         if (iachar(path(k:k)) < 32 .or. iachar(path(k:k)) == 127) then
            why = 'holds a control character (code ' // achar(48 + iachar(path(k:k))/100) &
               // achar(48 + mod(iachar(path(k:k))/10, 10)) // achar(48 + mod(iachar(path(k:k)), 10)) // ')'
            return
         end if
      end do
   end function path_problem

   !> Takes an exclusive lock on the file `path` (created empty if missing,
   !> never truncated) without waiting: stat = 1 when another process holds
   !> it (or the file cannot be opened), with the file named.
   subroutine lock_file(path, lock, stat, errmsg)
      character(len=*), intent(in) :: path          !< the file
      type(file_lock_t), intent(out) :: lock        !< the lock, held until unlock_file
      integer, intent(out) :: stat                  !< 0 when locked
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      integer(c_int) :: r
      stat = 1
      lock%stream = c_fopen(path // c_null_char, 'a' // c_null_char)
      if (.not. c_associated(lock%stream)) then
         errmsg = 'cannot open ' // path
         return
      end if
      r = c_flock(c_fileno(lock%stream), ior(lock_ex, lock_nb))
      if (r /= 0) then
         errmsg = path // ' is being written by another run now (it is locked)'
         call close_stream(lock%stream)
         return
      end if
      stat = 0
   end subroutine lock_file

   !> Releases a lock taken by lock_file (nothing when none is held).
   subroutine unlock_file(lock)
      type(file_lock_t), intent(inout) :: lock      !< the lock
      call close_stream(lock%stream)
   end subroutine unlock_file

   !> Replaces the file `to` by `from` in one step (rename(2)).
   subroutine rename_file(from, to, stat, errmsg)
      character(len=*), intent(in) :: from, to      !< the paths
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      stat = int(c_rename(from // c_null_char, to // c_null_char))
      if (stat /= 0) errmsg = 'cannot rename ' // from // ' to ' // to
   end subroutine rename_file

   !> Cuts the file `path` to `length` bytes (truncate(2)); stat /= 0 when
   !> it cannot.
   subroutine truncate_file(path, length, stat)
      character(len=*), intent(in) :: path          !< the file
      integer(int64), intent(in) :: length          !< its new length (bytes)
      integer, intent(out) :: stat                  !< 0 on success
      stat = int(c_truncate(path // c_null_char, int(length, c_int64_t)))
   end subroutine truncate_file

   !> The length of the file `path` on disk (bytes), -1 when it cannot be
   !> opened.
   function file_size(path) result(bytes)
      character(len=*), intent(in) :: path          !< the file
      integer(int64) :: bytes
      type(file_probe_t) :: probe
      integer :: stat
      bytes = -1
      call open_probe(path, probe, stat)
      if (stat /= 0) return
      bytes = probe_size(probe)
      call close_probe(probe)
   end function file_size

   !> Opens `path` for reading its length (stat /= 0 when it cannot).
   subroutine open_probe(path, probe, stat)
      character(len=*), intent(in) :: path          !< the file
      type(file_probe_t), intent(out) :: probe      !< the probe, open on success
      integer, intent(out) :: stat                  !< 0 on success
      probe%stream = c_fopen(path // c_null_char, 'r' // c_null_char)
      stat = merge(0, 1, c_associated(probe%stream))
   end subroutine open_probe

   !> The length on disk of the probe's file (bytes), -1 when it is not open.
   function probe_size(probe) result(bytes)
      type(file_probe_t), intent(in) :: probe       !< an open probe
      integer(int64) :: bytes
      bytes = -1
      if (c_associated(probe%stream)) bytes = int(c_lseek(c_fileno(probe%stream), 0_c_int64_t, seek_end), int64)
   end function probe_size

   !> Closes a probe (nothing when it is not open).
   subroutine close_probe(probe)
      type(file_probe_t), intent(inout) :: probe    !< the probe
      call close_stream(probe%stream)
   end subroutine close_probe

   !> Closes a C stream (fclose) if open; null on return.
   subroutine close_stream(stream)
      type(c_ptr), intent(inout) :: stream          !< the stream
      integer(c_int) :: r
      if (c_associated(stream)) r = c_fclose(stream)
      stream = c_null_ptr
   end subroutine close_stream

end module file_system
