!> Reads a run's <prefix>_summary.dat (result_files, write_summary_file): after the '#'
!> lines, one 'key = value' line per item, the unit in the key's name.
module summary_reader
   use kinds, only: dp, msg_len
   implicit none
   private
   public :: summary_t, read_summary, summary_value, summary_has, summary_index

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

end module summary_reader
