!> The pieces of a restart file (src/record/restart_point.f90): a stream of
!> unformatted records, each part behind an eight-character tag the reader
!> checks; every routine keeps the first failure in `stat`. Values, vectors,
!> an impactor (eq. 16, 21), a contact load pattern, and the seal: the last
!> 8 bytes, zlib's CRC-32 of all before them. More: docs/ROBUSTNESS.md.
module restart_io
   use, intrinsic :: iso_fortran_env, only: int8, int64
   use kinds, only: dp
   use newmark, only: impactor_t
   use contact_load, only: load_pattern_t
   implicit none
   private
   public :: put_tag, take_tag, put_text, take_text, put_value, take_value, put_array, take_reals, take_ints, &
             put_impactor, take_impactor, put_pattern, take_pattern, put_seal, seal_holds

   !> Characters of a tag.
   integer, parameter :: tag_len = 8
   !> stat when a tag is not the one expected.
   integer, parameter :: wrong_tag = -100
   !> CRC-32's polynomial, reflected, and its initial and final mask.
   integer(int64), parameter :: crc_poly = int(z'EDB88320', int64), crc_mask = int(z'FFFFFFFF', int64)

contains

   !> Writes the tag of a part.
   subroutine put_tag(u, tag, stat)
      integer, intent(in) :: u                      !< the open stream
      character(len=*), intent(in) :: tag           !< the part's name (tag_len characters at most)
      integer, intent(inout) :: stat                !< 0, or the first failure
      character(len=tag_len) :: t
      if (stat /= 0) return
      t = tag
      write (u, iostat=stat) t
   end subroutine put_tag

   !> Reads a tag: stat /= 0 unless it is `tag`.
   subroutine take_tag(u, tag, stat)
      integer, intent(in) :: u                      !< the open stream
      character(len=*), intent(in) :: tag           !< the part expected
      integer, intent(inout) :: stat                !< 0, or the first failure
      character(len=tag_len) :: t
      if (stat /= 0) return
      read (u, iostat=stat) t
      if (stat == 0 .and. t /= tag) stat = wrong_tag
   end subroutine take_tag

   !> A text: its length, then its characters.
   subroutine put_text(u, text, stat)
      integer, intent(in) :: u                      !< the open stream
      character(len=*), intent(in) :: text          !< the text
      integer, intent(inout) :: stat                !< 0, or the first failure
      if (stat /= 0) return
      write (u, iostat=stat) len(text)
      if (stat == 0 .and. len(text) > 0) write (u, iostat=stat) text
   end subroutine put_text

   !> Reads a text written by put_text.
   subroutine take_text(u, text, stat)
      integer, intent(in) :: u                      !< the open stream
      character(len=:), allocatable, intent(out) :: text   !< the text
      integer, intent(inout) :: stat                !< 0, or the first failure
      integer :: n
      text = ''
      if (stat /= 0) return
      read (u, iostat=stat) n
      if (stat /= 0) return
      if (n < 0 .or. n > 10**7) then
         stat = wrong_tag
         return
      end if
      text = repeat(' ', n)
      if (n > 0) read (u, iostat=stat) text
   end subroutine take_text

   !> One value: a real(dp), an integer, or a logical as the integer 0 or 1.
   subroutine put_value(u, x, stat)
      integer, intent(in) :: u                      !< the open stream
      class(*), intent(in) :: x                     !< the value
      integer, intent(inout) :: stat                !< 0, or the first failure
      if (stat /= 0) return
      select type (x)
      type is (real(dp))
         write (u, iostat=stat) x
      type is (integer)
         write (u, iostat=stat) x
      type is (logical)
         write (u, iostat=stat) merge(1, 0, x)
      class default
         stat = wrong_tag
      end select
   end subroutine put_value

   !> Reads a value written by put_value (unchanged after a failure).
   subroutine take_value(u, x, stat)
      integer, intent(in) :: u                      !< the open stream
      class(*), intent(inout) :: x                  !< the value
      integer, intent(inout) :: stat                !< 0, or the first failure
      integer :: i
      if (stat /= 0) return
      select type (x)
      type is (real(dp))
         read (u, iostat=stat) x
      type is (integer)
         read (u, iostat=stat) x
      type is (logical)
         read (u, iostat=stat) i
         if (stat == 0) x = i /= 0
      end select
   end subroutine take_value

   !> A vector of reals or integers: its size, then its values.
   subroutine put_array(u, x, stat)
      integer, intent(in) :: u                      !< the open stream
      class(*), intent(in) :: x(:)                  !< the values
      integer, intent(inout) :: stat                !< 0, or the first failure
      call put_value(u, size(x), stat)
      if (stat /= 0 .or. size(x) == 0) return
      select type (x)
      type is (real(dp))
         write (u, iostat=stat) x
      type is (integer)
         write (u, iostat=stat) x
      end select
   end subroutine put_array

   !> Reads a vector written by put_array; with `n`, its size must be n.
   subroutine take_reals(u, x, stat, n)
      integer, intent(in) :: u                      !< the open stream
      real(dp), allocatable, intent(inout) :: x(:)  !< the values
      integer, intent(inout) :: stat                !< 0, or the first failure
      integer, intent(in), optional :: n            !< the size expected
      integer :: m
      call take_size(u, m, stat, n)
      if (stat /= 0) return
      if (allocated(x)) deallocate (x)
      allocate (x(m))
      if (m > 0) read (u, iostat=stat) x
   end subroutine take_reals

   !> Reads a vector of integers written by put_array; with `n`, its size must be n.
   subroutine take_ints(u, i, stat, n)
      integer, intent(in) :: u                      !< the open stream
      integer, allocatable, intent(inout) :: i(:)   !< the values
      integer, intent(inout) :: stat                !< 0, or the first failure
      integer, intent(in), optional :: n            !< the size expected
      integer :: m
      call take_size(u, m, stat, n)
      if (stat /= 0) return
      if (allocated(i)) deallocate (i)
      allocate (i(m))
      if (m > 0) read (u, iostat=stat) i
   end subroutine take_ints

   !> A vector's size; stat /= 0 when it is out of range or, with `n`, not n.
   subroutine take_size(u, m, stat, n)
      integer, intent(in) :: u                      !< the open stream
      integer, intent(out) :: m                     !< the size
      integer, intent(inout) :: stat                !< 0, or the first failure
      integer, intent(in), optional :: n            !< the size expected
      m = -1
      call take_value(u, m, stat)
      if (stat == 0 .and. (m < 0 .or. m > 10**9)) stat = wrong_tag
      if (present(n) .and. stat == 0) then
         if (m /= n) stat = wrong_tag
      end if
   end subroutine take_size

   !> An impactor: mass, position, velocity, force.
   subroutine put_impactor(u, imp, stat)
      integer, intent(in) :: u                      !< the open stream
      type(impactor_t), intent(in) :: imp           !< the impactor
      integer, intent(inout) :: stat                !< 0, or the first failure
      call put_array(u, [imp%mass, imp%w, imp%v, imp%f], stat)
   end subroutine put_impactor

   !> Reads an impactor written by put_impactor.
   subroutine take_impactor(u, imp, stat)
      integer, intent(in) :: u                      !< the open stream
      type(impactor_t), intent(inout) :: imp        !< the impactor
      integer, intent(inout) :: stat                !< 0, or the first failure
      real(dp), allocatable :: x(:)
      call take_reals(u, x, stat, 4)
      if (stat == 0) imp = impactor_t(mass=x(1), w=x(2), v=x(3), f=x(4))
   end subroutine take_impactor

   !> A contact load pattern, whole, with its cached polynomials (the same bits after a restart).
   subroutine put_pattern(u, p, stat)
      integer, intent(in) :: u                      !< the open stream
      type(load_pattern_t), intent(in) :: p         !< the pattern
      integer, intent(inout) :: stat                !< 0, or the first failure
      logical :: has_poly
      call put_array(u, [p%radius, p%total, p%valid, p%built_for], stat)
      call put_value(u, p%n, stat)
      if (p%n > 0) call put_array(u, p%eq(:p%n), stat)
      if (p%n > 0) call put_array(u, p%c(:p%n), stat)
      has_poly = allocated(p%poly)
      if (has_poly) has_poly = p%n > 0 .and. size(p%poly, 2) >= p%n
      call put_value(u, has_poly, stat)
      if (has_poly) call put_array(u, reshape(p%poly(:, :p%n), [5*p%n]), stat)
   end subroutine put_pattern

   !> Reads a pattern written by put_pattern.
   subroutine take_pattern(u, p, stat)
      integer, intent(in) :: u                      !< the open stream
      type(load_pattern_t), intent(inout) :: p      !< the pattern
      integer, intent(inout) :: stat                !< 0, or the first failure
      real(dp), allocatable :: x(:)
      integer, allocatable :: eq(:)
      logical :: has_poly
      call take_reals(u, x, stat, 10)
      if (stat /= 0) return
      p%radius = x(1);  p%total = x(2);  p%valid = x(3:4);  p%built_for = x(5:10)
      call take_value(u, p%n, stat)
      if (stat /= 0) return
      if (p%n > 0) then
         call take_ints(u, eq, stat)
         call take_reals(u, x, stat, p%n)
         if (stat /= 0) return
         p%eq = eq
         p%c = x
      else
         p%eq = [integer ::]
         p%c = [real(dp) ::]
      end if
      has_poly = .false.
      call take_value(u, has_poly, stat)
      if (has_poly) call take_reals(u, x, stat, 5*p%n)
      if (.not. has_poly .or. stat /= 0) return
      if (allocated(p%poly)) deallocate (p%poly)
      allocate (p%poly(0:4, p%n))             ! (lower bound 0: the power of the radius)
      p%poly(:, :) = reshape(x, [5, p%n])
   end subroutine take_pattern

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
