!> The pieces of a restart file (src/record/restart_point.f90): a stream of unformatted records,
!> each part behind an eight-character tag the reader checks. One routine per piece both writes and
!> reads it (restart_stream_t's direction), which keeps the two in step; the first failure stays in
!> `stat`. Values, vectors, an impactor (eq. 16, 21), a contact load pattern, and the seal: the last
!> 8 bytes, zlib's CRC-32 of all before them. More: docs/ROBUSTNESS.md.
module restart_io
   use, intrinsic :: iso_fortran_env, only: int8, int64
   use kinds, only: dp
   use newmark, only: impactor_t
   use contact_load, only: load_pattern_t
   implicit none
   private
   public :: restart_stream_t, io_tag, io_text, io_value, io_values, io_count, io_block, io_array, io_ints, &
             io_impactor, io_pattern, put_seal, seal_holds

   !> An open restart file and the direction its pieces go.
   type :: restart_stream_t
      integer :: u = -1                             !< the open stream
      logical :: reading = .false.                  !< read and checked (else written)
      integer :: stat = 0                           !< 0, or the first failure
   end type restart_stream_t

   !> A vector of reals or integers, rank 1 or 2: its size, then its values.
   interface io_array
      module procedure io_array1, io_array2
   end interface io_array

   !> Characters of a tag.
   integer, parameter :: tag_len = 8
   !> stat when a tag is not the one expected.
   integer, parameter :: wrong_tag = -100
   !> CRC-32's polynomial, reflected, and its initial and final mask.
   integer(int64), parameter :: crc_poly = int(z'EDB88320', int64), crc_mask = int(z'FFFFFFFF', int64)

contains

   !> The tag of a part; read, stat /= 0 unless it is `tag`.
   subroutine io_tag(s, tag)
      type(restart_stream_t), intent(inout) :: s    !< the restart file
      character(len=*), intent(in) :: tag           !< the part's name (tag_len characters at most)
      character(len=tag_len) :: t
      if (s%stat /= 0) return
      t = tag
      if (s%reading) read (s%u, iostat=s%stat) t
      if (.not. s%reading) write (s%u, iostat=s%stat) t
      if (s%stat == 0 .and. t /= tag) s%stat = wrong_tag
   end subroutine io_tag

   !> A text: its length, then its characters.
   subroutine io_text(s, text)
      type(restart_stream_t), intent(inout) :: s    !< the restart file
      character(len=:), allocatable, intent(inout) :: text   !< the text
      integer :: n
      if (.not. allocated(text)) text = ''
      n = len(text)
      call io_value(s, n)
      if (s%stat /= 0) return
      if (n < 0 .or. n > 10**7) then
         s%stat = wrong_tag
         return
      end if
      if (s%reading) text = repeat(' ', n)
      if (n > 0 .and. s%reading) read (s%u, iostat=s%stat) text
      if (n > 0 .and. .not. s%reading) write (s%u, iostat=s%stat) text
   end subroutine io_text

   !> One value: a real(dp), an integer, or a logical as the integer 0 or 1.
   recursive subroutine io_value(s, x)
      type(restart_stream_t), intent(inout) :: s    !< the restart file
      class(*), intent(inout) :: x                  !< the value (unchanged after a failure)
      integer :: i
      if (s%stat /= 0) return
      select type (x)
      type is (real(dp))
         if (s%reading) read (s%u, iostat=s%stat) x
         if (.not. s%reading) write (s%u, iostat=s%stat) x
      type is (integer)
         if (s%reading) read (s%u, iostat=s%stat) x
         if (.not. s%reading) write (s%u, iostat=s%stat) x
      type is (logical)
         i = merge(1, 0, x)
         call io_value(s, i)
         if (s%stat == 0) x = i /= 0
      class default
         s%stat = wrong_tag
      end select
   end subroutine io_value

   !> Up to seven values in a row (io_value).
   subroutine io_values(s, a, b, c, d, e, f, g)
      type(restart_stream_t), intent(inout) :: s    !< the restart file
      class(*), intent(inout) :: a                  !< the first value
      class(*), intent(inout), optional :: b, c, d, e, f, g   !< the next ones
      call io_value(s, a)
      if (present(b)) call io_value(s, b)
      if (present(c)) call io_value(s, c)
      if (present(d)) call io_value(s, d)
      if (present(e)) call io_value(s, e)
      if (present(f)) call io_value(s, f)
      if (present(g)) call io_value(s, g)
   end subroutine io_values

   !> The size of the vector that follows, `n`; read, stat /= 0 unless it is n.
   subroutine io_count(s, n)
      type(restart_stream_t), intent(inout) :: s    !< the restart file
      integer, intent(in) :: n                      !< the size
      integer :: m
      m = n
      call io_value(s, m)
      if (s%stat == 0 .and. m /= n) s%stat = wrong_tag
   end subroutine io_count

   !> Values of reals, integers or logicals (as 0 or 1), without their size.
   recursive subroutine io_block(s, x)
      type(restart_stream_t), intent(inout) :: s    !< the restart file
      class(*), intent(inout) :: x(:)               !< the values
      integer, allocatable :: i(:)
      if (s%stat /= 0 .or. size(x) == 0) return
      select type (x)
      type is (real(dp))
         if (s%reading) read (s%u, iostat=s%stat) x
         if (.not. s%reading) write (s%u, iostat=s%stat) x
      type is (integer)
         if (s%reading) read (s%u, iostat=s%stat) x
         if (.not. s%reading) write (s%u, iostat=s%stat) x
      type is (logical)
         i = merge(1, 0, x)
         call io_block(s, i)
         if (s%stat == 0) x = i /= 0
      class default
         s%stat = wrong_tag
      end select
   end subroutine io_block

   !> A vector of its size: its size, then its values.
   subroutine io_array1(s, x)
      type(restart_stream_t), intent(inout) :: s    !< the restart file
      class(*), intent(inout) :: x(:)               !< the values
      call io_count(s, size(x))
      call io_block(s, x)
   end subroutine io_array1

   !> A matrix of its shape, as the vector of its values in Fortran order.
   subroutine io_array2(s, x)
      type(restart_stream_t), intent(inout) :: s    !< the restart file
      class(*), intent(inout) :: x(:,:)             !< the values
      integer :: j
      call io_count(s, size(x))
      do j = 1, size(x, 2)
         call io_block(s, x(:, j))
      end do
   end subroutine io_array2

   !> A vector of integers of any size.
   subroutine io_ints(s, i)
      type(restart_stream_t), intent(inout) :: s    !< the restart file
      integer, allocatable, intent(inout) :: i(:)   !< the values
      integer :: m
      if (.not. allocated(i)) allocate (i(0))
      m = size(i)
      call io_value(s, m)
      if (s%stat == 0 .and. s%reading .and. (m < 0 .or. m > 10**9)) s%stat = wrong_tag
      if (s%stat /= 0) return
      if (s%reading) deallocate (i)
      if (s%reading) allocate (i(m))
      call io_block(s, i)
   end subroutine io_ints

   !> An impactor: mass, position, velocity, force.
   subroutine io_impactor(s, imp)
      type(restart_stream_t), intent(inout) :: s    !< the restart file
      type(impactor_t), intent(inout) :: imp        !< the impactor
      call io_count(s, 4)
      call io_values(s, imp%mass, imp%w, imp%v, imp%f)
   end subroutine io_impactor

   !> A contact load pattern, whole, with its cached polynomials (the same bits after a restart).
   subroutine io_pattern(s, p)
      type(restart_stream_t), intent(inout) :: s    !< the restart file
      type(load_pattern_t), intent(inout) :: p      !< the pattern
      real(dp), allocatable :: c(:)
      integer, allocatable :: eq(:)
      logical :: has_poly
      call io_count(s, 10)
      call io_values(s, p%radius, p%total)
      call io_block(s, p%valid)
      call io_block(s, p%built_for)
      call io_value(s, p%n)
      if (s%stat /= 0) return
      allocate (eq(max(p%n, 0)), c(max(p%n, 0)))
      if (p%n > 0 .and. .not. s%reading) eq = p%eq(:p%n)
      if (p%n > 0 .and. .not. s%reading) c = p%c(:p%n)
      if (p%n > 0) call io_array(s, eq)
      if (p%n > 0) call io_array(s, c)
      if (s%stat /= 0) return
      if (s%reading) p%eq = eq
      if (s%reading) p%c = c
      has_poly = .false.
      if (allocated(p%poly) .and. .not. s%reading) has_poly = p%n > 0 .and. size(p%poly, 2) >= p%n
      call io_value(s, has_poly)
      if (.not. has_poly .or. s%stat /= 0) return
      if (s%reading) then
         if (allocated(p%poly)) deallocate (p%poly)
         allocate (p%poly(0:4, p%n))            ! (lower bound 0: the power of the radius)
      end if
      call io_array(s, p%poly(:, :p%n))
   end subroutine io_pattern

   !> Appends the CRC-32 of all `u` holds (opened with action = 'readwrite').
   subroutine put_seal(u, stat)
      integer, intent(in) :: u                      !< the open stream, at its end
      integer, intent(inout) :: stat                !< 0, or the first failure
      integer(int8), allocatable :: bytes(:)
      integer :: next
      if (stat /= 0) return
      inquire (unit=u, pos=next, iostat=stat)
      if (stat /= 0) return
      allocate (bytes(next - 1))
      if (next > 1) read (u, pos=1, iostat=stat) bytes
      if (stat == 0) write (u, pos=next, iostat=stat) crc32(bytes)
   end subroutine put_seal

   !> The file on `u` ends with the CRC-32 of all before it; `u` back at its start.
   logical function seal_holds(u) result(holds)
      integer, intent(in) :: u                      !< the open stream
      integer(int8), allocatable :: bytes(:)
      integer(int64) :: n, seal
      integer :: ios
      holds = .false.
      inquire (unit=u, size=n, iostat=ios)
      if (ios /= 0 .or. n < 9 .or. n > huge(1)) return
      allocate (bytes(n - 8))
      read (u, pos=1, iostat=ios) bytes, seal
      if (ios == 0) holds = seal == crc32(bytes)
      if (ios == 0) read (u, pos=1, iostat=ios)
   end function seal_holds

   !> The CRC-32 of `bytes` (IEEE 802.3, as zlib's crc32), in [0, 2**32).
   pure function crc32(bytes) result(crc)
      integer(int8), intent(in) :: bytes(:)         !< the data
      integer(int64) :: crc
      integer(int64) :: table(0:255), c
      integer :: i, k
      do i = 0, 255
         c = i
         do k = 1, 8
            c = merge(ieor(shiftr(c, 1), crc_poly), shiftr(c, 1), iand(c, 1_int64) /= 0)
         end do
         table(i) = c
      end do
      crc = crc_mask
      do i = 1, size(bytes)
         crc = ieor(table(iand(ieor(crc, int(bytes(i), int64)), 255_int64)), shiftr(crc, 8))
      end do
      crc = ieor(crc, crc_mask)
   end function crc32

end module restart_io
