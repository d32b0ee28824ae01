!> What the program asks of the file system, through the C library, never a shell (a path is
!> only a name): directories, advisory locks (flock(2)), rename, truncate, a file's size on
!> disk, what a name is without following a link, the paths and prefixes refused, exclusive
!> creation and removal, lines of any length. No write goes through a symbolic link. Not from
!> the paper. More: docs/ROBUSTNESS.md.
module file_system
   use, intrinsic :: iso_c_binding, only: c_int, c_null_char, c_ptr, c_null_ptr, c_associated, c_int64_t
   use, intrinsic :: iso_fortran_env, only: int64, iostat_end, iostat_eor
   use number_text, only: int_str
   use c_library, only: c_mkdir, c_fopen, c_lseek, c_fclose, c_fileno, c_rename, c_truncate, c_flock
   use c_library, only: statx_t, c_statx, c_unlink
   implicit none
   private
   public :: make_directories, parent_directory, nearest_directory, path_problem, prefix_problem, name_problem
   public :: short_path, path_kind, path_missing, path_regular, path_link, path_directory, path_other
   public :: create_new_file, remove_file
   public :: file_lock_t, lock_file, unlock_file, rename_file, truncate_file, file_size
   public :: file_probe_t, open_probe, probe_size, close_probe, read_line

   !> A lock taken by lock_file: the stream it holds open.
   type :: file_lock_t
      type(c_ptr) :: stream = c_null_ptr
   end type file_lock_t

   !> A file kept open for reading its length (open_probe): its stream.
   type :: file_probe_t
      type(c_ptr) :: stream = c_null_ptr
   end type file_probe_t

   !> Characters read_line reads at a time.
   integer, parameter :: chunk_len = 256
   !> lseek's whence SEEK_END: from the end of the file (<unistd.h>).
   integer(c_int), parameter :: seek_end = 2
   !> flock(2) operations (Linux, <sys/file.h>): exclusive, do not wait.
   integer(c_int), parameter :: lock_ex = 2, lock_nb = 4

   !> Permissions of a directory created here, before the umask: rwxrwxrwx.
   integer(c_int), parameter :: dir_mode = int(o'777', c_int)

   !> What a name is (path_kind).
   integer, parameter :: path_missing = 0, path_regular = 1, path_link = 2, path_directory = 3, path_other = 4
   !> statx(2) (<fcntl.h>, <linux/stat.h>): the working directory, do not
   !> follow a last link, the descriptor itself; the type and inode wanted.
   integer(c_int), parameter :: at_fdcwd = -100, at_symlink_nofollow = int(z'100'), at_empty_path = int(z'1000')
   integer(c_int), parameter :: statx_type = 1, statx_ino = int(z'100')
   !> File types of stx_mode (<sys/stat.h>).
   integer, parameter :: s_ifmt = int(o'170000'), s_iflnk = int(o'120000'), s_ifreg = int(o'100000'), &
                         s_ifdir = int(o'040000')
   !> Characters of a path a message shows before it is cut in the middle.
   integer, parameter :: shown_path_len = 120

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
      character(len=len_trim(dir) + 1) :: ended
      integer :: k
      integer(c_int) :: r
      logical :: exists
      stat = 0
      if (len_trim(dir) == 0) return
      ended = trim(dir) // '/'      ! every prefix ending before a '/', the whole path the last
      do k = 2, len(ended)
         if (ended(k:k) /= '/') cycle
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
      if (len_trim(path) == 0) why = 'must not be empty'    ! (blanks: no control character)
      do k = 1, len(path)
         if (iachar(path(k:k)) < 32 .or. iachar(path(k:k)) == 127) then
            why = 'holds a control character (code ' // achar(48 + iachar(path(k:k))/100) &
               // achar(48 + mod(iachar(path(k:k))/10, 10)) // achar(48 + mod(iachar(path(k:k)), 10)) // ')'
            return
         end if
      end do
   end function path_problem

   !> Why a results prefix cannot be used, '' when it can: path_problem's reasons, and a prefix
   !> whose last part is no name ('out/', '.', 'out/..'), which would make hidden files in a
   !> directory (out/_history.dat, out/.h5).
   pure function prefix_problem(prefix) result(why)
      character(len=*), intent(in) :: prefix
      character(len=:), allocatable :: why
      character(len=:), allocatable :: last
      why = path_problem(prefix)
      if (len(why) > 0) return
      last = prefix(index(prefix, '/', back=.true.) + 1:)
      if (len(last) == 0) then
         why = "ends with '/': it names a directory, and the result files would be hidden files in it " &
            // "(" // short_path(prefix) // "_history.dat): end it with a name, e.g. '" // short_path(prefix) // "run'"
      else if (last == '.' .or. last == '..') then
         why = "ends with '" // last // "': it names a directory, and the result files would be hidden files " &
            // "(" // short_path(prefix) // "_history.dat): end it with a name, e.g. '" // short_path(prefix) // "/run'"
      end if
   end function prefix_problem

   !> Why `path` cannot be a file's name on a file system whose names have at most name_max
   !> bytes and whose paths at most path_max - 1 (NAME_MAX, PATH_MAX), '' when it can: the
   !> first part between slashes that is too long, or the whole path.
   pure function name_problem(path, name_max, path_max) result(why)
      character(len=*), intent(in) :: path          !< the file's path
      integer, intent(in) :: name_max               !< NAME_MAX (255 on Linux's file systems)
      integer, intent(in) :: path_max               !< PATH_MAX (4096 on Linux), with the final NUL
      character(len=:), allocatable :: why
      integer :: from, slash
      why = ''
      if (len(path) >= path_max) then
         why = 'the path ' // short_path(path) // ' has ' // int_str(len(path)) // ' bytes, more than the ' &
            // int_str(path_max - 1) // ' a path may have (PATH_MAX)'
         return
      end if
      from = 1
      do while (from <= len(path))
         slash = index(path(from:), '/')
         if (slash == 0) slash = len(path) - from + 2
         if (slash - 1 > name_max) then
            why = 'the name ' // short_path(path(from:from + slash - 2)) // ' has ' // int_str(slash - 1) &
               // ' bytes, more than the ' // int_str(name_max) // ' a file name may have on this file system ' &
               // '(NAME_MAX): a shorter prefix'
            return
         end if
         from = from + slash
      end do
   end function name_problem

   !> A path as a message shows it: whole up to shown_path_len characters,
   !> else its start and its end (where the file's own name is) around '...'.
   pure function short_path(path) result(shown)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: shown
      integer, parameter :: head = shown_path_len/2 - 3
      if (len(path) <= shown_path_len) then
         shown = path
      else
         shown = path(:head) // '...' // path(len(path) - (shown_path_len - head - 3) + 1:)
      end if
   end function short_path

   !> The nearest existing directory above a path, the one its file is or would be in: its
   !> parents in turn, then '.' (or '/' for an absolute path).
   function nearest_directory(path) result(dir)
      character(len=*), intent(in) :: path   !< a file's path, existing or not
      character(len=:), allocatable :: dir
      logical :: exists
      dir = path
      do
         dir = parent_directory(dir)
         if (len(dir) == 0) then
            dir = merge('/', '.', path(1:min(1, len(path))) == '/')
            return
         end if
         inquire (file=dir // '/.', exist=exists)
         if (exists) return
      end do
   end function nearest_directory

   !> What the name `path` is, itself (a symbolic link is path_link, not
   !> what it points to): path_missing, path_regular, path_link,
   !> path_directory or path_other (a device, a pipe, a socket).
   function path_kind(path) result(kind)
      character(len=*), intent(in) :: path
      integer :: kind
      type(statx_t) :: buf
      logical :: exists
      if (c_statx(at_fdcwd, path // c_null_char, at_symlink_nofollow, statx_type, buf) /= 0) then
         inquire (file=path, exist=exists)     ! no statx (Linux before 4.11): what the run-time says
         kind = merge(path_regular, path_missing, exists)
         return
      end if
      select case (iand(int(buf%stx_mode), s_ifmt))
      case (s_iflnk); kind = path_link
      case (s_ifreg); kind = path_regular
      case (s_ifdir); kind = path_directory
      case default;   kind = path_other
      end select
   end function path_kind

   !> Creates the file `path`, empty, exclusively: stat /= 0 when a file,
   !> a directory or a symbolic link (even a dangling one) has that name
   !> (O_CREAT | O_EXCL: Fortran's status = 'new'), or it cannot be made.
   subroutine create_new_file(path, stat, errmsg)
      character(len=*), intent(in) :: path          !< the file
      integer, intent(out) :: stat                  !< 0 when it was created
      character(len=*), intent(inout) :: errmsg     !< the run-time's reason on failure
      integer :: u, ios
      open (newunit=u, file=path, status='new', action='write', iostat=stat, iomsg=errmsg)
      if (stat == 0) close (u, iostat=ios)
   end subroutine create_new_file

   !> Removes the name `path` (unlink(2): a symbolic link itself, never what
   !> it points to); stat /= 0 when it cannot (or there is none).
   subroutine remove_file(path, stat)
      character(len=*), intent(in) :: path          !< the name
      integer, intent(out) :: stat                  !< 0 when removed
      stat = int(c_unlink(path // c_null_char))
   end subroutine remove_file

   !> Takes an exclusive lock on the existing file `path` without waiting
   !> (flock(2), the file opened for reading); stat = 1, the file named, when
   !> another process holds it, it cannot be opened, or the name no longer
   !> holds the locked file (a symbolic link, or another run's file, in its place).
   subroutine lock_file(path, lock, stat, errmsg)
      character(len=*), intent(in) :: path          !< the file
      type(file_lock_t), intent(out) :: lock        !< the lock, held until unlock_file
      integer, intent(out) :: stat                  !< 0 when locked
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      stat = 1
      lock%stream = c_fopen(path // c_null_char, 're' // c_null_char)
      if (.not. c_associated(lock%stream)) then
         errmsg = 'cannot open ' // short_path(path)
         return
      end if
      if (c_flock(c_fileno(lock%stream), ior(lock_ex, lock_nb)) /= 0) then
         errmsg = short_path(path) // ' is being written by another run now (it is locked)'
      else if (.not. name_holds(path, c_fileno(lock%stream))) then
         errmsg = short_path(path) // ' was replaced while this run claimed it (by another run with the same ' &
            // 'prefix, or a symbolic link)'
      else
         stat = 0
      end if
      if (stat /= 0) call close_stream(lock%stream)
   end subroutine lock_file

   !> The name `path`, itself a regular file and no link, is the file open
   !> on descriptor fd (the same device and inode); true when statx is
   !> missing (Linux before 4.11) and it cannot be told.
   logical function name_holds(path, fd)
      character(len=*), intent(in) :: path          !< the name
      integer(c_int), intent(in) :: fd              !< an open descriptor
      type(statx_t) :: by_name, by_fd
      name_holds = .true.
      if (c_statx(fd, c_null_char, at_empty_path, ior(statx_type, statx_ino), by_fd) /= 0) return
      name_holds = .false.
      if (c_statx(at_fdcwd, path // c_null_char, at_symlink_nofollow, ior(statx_type, statx_ino), by_name) /= 0) return
      name_holds = iand(int(by_name%stx_mode), s_ifmt) == s_ifreg .and. by_name%stx_ino == by_fd%stx_ino &
         .and. by_name%stx_dev_major == by_fd%stx_dev_major .and. by_name%stx_dev_minor == by_fd%stx_dev_minor
   end function name_holds

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

   !> Cuts the file `path` to `length` bytes (truncate(2)); stat /= 0 when it cannot.
   subroutine truncate_file(path, length, stat)
      character(len=*), intent(in) :: path          !< the file
      integer(int64), intent(in) :: length          !< its new length (bytes)
      integer, intent(out) :: stat                  !< 0 on success
      stat = int(c_truncate(path // c_null_char, int(length, c_int64_t)))
   end subroutine truncate_file

   !> The length of the file `path` on disk (bytes), -1 when it cannot be opened.
   function file_size(path) result(bytes)
      character(len=*), intent(in) :: path          !< the file
      integer(int64) :: bytes
      type(file_probe_t) :: probe
      integer :: stat
      call open_probe(path, probe, stat)
      bytes = probe_size(probe)                     ! -1 when not open
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

   !> One line of any length, read in chunks into a buffer that doubles;
   !> ios = iostat_end at the end of the file. over is true (and the
   !> reading stops) when the line is longer than `budget` bytes.
   subroutine read_line(unit, budget, line, ios, msg, over)
      integer, intent(in) :: unit                          !< an open formatted unit
      integer, intent(in) :: budget                        !< bytes the line may have
      character(len=:), allocatable, intent(out) :: line   !< the line, without its end of line
      integer, intent(out) :: ios                          !< 0, iostat_end, or the read's error
      character(len=*), intent(inout) :: msg               !< the read's message on an error
      logical, intent(out) :: over                         !< the line is longer than budget
      character(len=chunk_len) :: chunk
      character(len=:), allocatable :: buf
      integer :: nread, n
      allocate (character(len=chunk_len) :: buf)
      n = 0
      over = .false.
      do
         nread = 0
         read (unit, '(a)', advance='no', iostat=ios, iomsg=msg, size=nread) chunk
         if (ios == 0 .or. ios == iostat_eor) then
            if (n + nread > len(buf)) buf = buf // repeat(' ', len(buf))    ! doubled
            buf(n + 1:n + nread) = chunk(:nread)
            n = n + nread
            over = n > budget
            if (ios == iostat_eor .or. over) exit
         else
            if (ios == iostat_end .and. n > 0) ios = 0    ! a last line without its end of line
            exit
         end if
      end do
      if (ios == iostat_eor) ios = 0
      line = buf(:n)
   end subroutine read_line

end module file_system
