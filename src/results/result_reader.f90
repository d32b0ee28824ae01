!> Reads the result files result_files writes: the summary ('key = value'
!> lines after the '#' lines) and a column file (rows of numbers after the
!> '#' header). Not from the paper. More: docs/OUTPUT.md.
module result_reader
   use kinds, only: dp, msg_len
   implicit none
   private
   public :: summary_t, read_summary, summary_value, summary_string, summary_has, summary_index
   public :: read_columns

   !> The items of one summary, in the file's order.
   type :: summary_t
      character(len=64), allocatable :: keys(:)     !< the keys
      character(len=256), allocatable :: texts(:)   !< their values as written
   end type summary_t

contains

   !> Every 'key = value' line of the summary file `path`.
   subroutine read_summary(path, s, stat, errmsg)
      character(len=*), intent(in) :: path           !< <prefix>_summary.dat
      type(summary_t), intent(out) :: s              !< its items
      integer, intent(out) :: stat                   !< 0, or the failure to open or read it
      character(len=*), intent(inout) :: errmsg      !< what failed, naming the file
      character(len=1024) :: line
      character(len=msg_len) :: iomsg
      integer :: u, eq, ios
      allocate (s%keys(0), s%texts(0))
      open (newunit=u, file=path, status='old', action='read', iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         errmsg = 'cannot read ' // path // ': ' // trim(iomsg)
         return
      end if
      lines: do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit lines
         if (line(1:1) == '#') cycle lines
         eq = index(line, ' = ')
         if (eq < 2) cycle lines
         s%keys = [s%keys, line(:eq - 1)]
         s%texts = [s%texts, adjustl(line(eq + 3:))]
      end do lines
      close (u)
      if (size(s%keys) == 0) then
         stat = 1
         errmsg = path // ': no key = value line'
      end if
   end subroutine read_summary

   !> True when the summary has the key.
   pure logical function summary_has(s, key)
      type(summary_t), intent(in) :: s               !< the summary
      character(len=*), intent(in) :: key            !< the key
      summary_has = summary_index(s, key) > 0
   end function summary_has

   !> The item of the key, 0 when it is absent.
   pure integer function summary_index(s, key) result(i)
      type(summary_t), intent(in) :: s               !< the summary
      character(len=*), intent(in) :: key            !< the key
      do i = 1, size(s%keys)
         if (trim(s%keys(i)) == trim(key)) return
      end do
      i = 0
   end function summary_index

   !> The number of the key, `fallback` when the key is absent or its value is not a number.
   real(dp) function summary_value(s, key, fallback) result(x)
      type(summary_t), intent(in) :: s               !< the summary
      character(len=*), intent(in) :: key            !< the key
      real(dp), intent(in) :: fallback               !< the value of an absent key
      integer :: i, ios
      x = fallback
      i = summary_index(s, key)
      if (i == 0) return
      read (s%texts(i), *, iostat=ios) x
      if (ios /= 0) x = fallback
   end function summary_value

   !> The value of the key as written, '' when the key is absent.
   pure function summary_string(s, key) result(text)
      type(summary_t), intent(in) :: s               !< the summary
      character(len=*), intent(in) :: key            !< the key
      character(len=:), allocatable :: text
      integer :: i
      i = summary_index(s, key)
      text = ''
      if (i > 0) text = trim(s%texts(i))
   end function summary_string

   !> The rows of a column file, table(ncol, rows): each line's first ncol numbers.
   subroutine read_columns(path, ncol, table, stat)
      character(len=*), intent(in) :: path                 !< the file
      integer, intent(in) :: ncol                          !< columns to keep
      real(dp), allocatable, intent(out) :: table(:,:)     !< the rows
      integer, intent(out) :: stat                         !< 0; else the file is missing, empty or a row short
      character(len=2048) :: line
      integer :: u, ios, nrow, pass
      allocate (table(ncol, 0))
      open (newunit=u, file=path, status='old', action='read', iostat=stat)
      if (stat /= 0) return
      passes: do pass = 1, 2                 ! count, then read
         rewind (u)
         nrow = 0
         rows: do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit rows
            if (line(1:1) == '#' .or. len_trim(line) == 0) cycle rows
            nrow = nrow + 1
            if (pass == 1) cycle rows
            read (line, *, iostat=stat) table(:, nrow)
            if (stat /= 0) exit passes
         end do rows
         if (pass == 1) then
            deallocate (table)
            allocate (table(ncol, nrow))
         end if
      end do passes
      close (u)
      if (stat == 0 .and. nrow == 0) stat = 1
   end subroutine read_columns

end module result_reader
