!> What the program asks of the file system, through the C library (ISO C
!> binding), never through a shell: a path is only ever a name here, so
!> nothing in it is interpreted.
!>
!>  - make_directories: `mkdir -p` of a path's directories, by mkdir(2);
!>  - path_problem: a path the program refuses to use (empty, control
!>    characters);
!>  - rename_file: rename(2), which replaces the target in one step (a
!>    reader sees the old file or the new one, never half of one).
module file_system
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
   implicit none
   private
   public :: make_directories, parent_directory, path_problem, rename_file

   interface
      !> int mkdir(const char *path, mode_t mode)
      function c_mkdir(path, mode) bind(c, name='mkdir') result(r)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), value :: mode
         integer(c_int) :: r
      end function c_mkdir

      !> int rename(const char *oldpath, const char *newpath)
      function c_rename(oldpath, newpath) bind(c, name='rename') result(r)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: oldpath(*), newpath(*)
         integer(c_int) :: r
      end function c_rename
   end interface

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

   !> Renames the file `from` to `to`, replacing `to` in one step (same file
   !> system). stat /= 0 when it cannot, with both names in the message.
   subroutine rename_file(from, to, stat, errmsg)
      character(len=*), intent(in) :: from          !< the file
      character(len=*), intent(in) :: to            !< its new name
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< the names, on failure
      stat = 0
      if (c_rename(from // c_null_char, to // c_null_char) /= 0_c_int) then
         stat = 1
         errmsg = 'cannot rename ''' // from // ''' to ''' // to // ''''
      end if
   end subroutine rename_file

end module file_system
