!> The contact force's local maxima in a run's history file
!> (<prefix>_history.dat; its columns: history_columns of
!> src/results/result_files.f90, in the file's units): an accuracy run
!> reads them from each ladder run to see whether the time of the peak is
!> settled, i.e. no other maximum is within the peak force's error of
!> the highest (src/accuracy/accuracy_ladder.f90, peak_spread).
module history_reader
   use kinds, only: dp
   use result_files, only: history_columns
   implicit none
   private
   public :: maxima_t, force_maxima

   !> The local maxima kept: those at least this fraction of the largest (-).
   real(dp), parameter :: kept_fraction = 0.5_dp

   !> The local maxima of the force (a row above the one before and not
   !> below the one after), the file's units.
   type :: maxima_t
      real(dp), allocatable :: t_us(:)            !< their times (us)
      real(dp), allocatable :: f_n(:)             !< their forces (N)
   end type maxima_t

contains

   !> The maxima of the history file at path; none (size 0) when it
   !> cannot be read.
   subroutine force_maxima(path, mx)
      character(len=*), intent(in) :: path        !< <prefix>_history.dat
      type(maxima_t), intent(out) :: mx           !< its maxima
      character(len=4096) :: line
      real(dp), allocatable :: row(:)
      real(dp) :: t(3), f(3)
      integer :: u, ios, ct, cf, rows
      allocate (mx%t_us(0), mx%f_n(0))
      ct = findloc(history_columns%name, 'time', dim=1)
      cf = findloc(history_columns%name, 'force', dim=1)
      allocate (row(max(ct, cf)))
      open (newunit=u, file=path, status='old', action='read', iostat=ios)
      if (ios /= 0) return
      rows = 0
      t = 0.0_dp;  f = 0.0_dp
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:1) == '#' .or. len_trim(line) == 0) cycle
         read (line, *, iostat=ios) row
         if (ios /= 0) exit
         rows = rows + 1
         t = [t(2:3), row(ct)];  f = [f(2:3), row(cf)]
         if (rows >= 3 .and. f(2) > f(1) .and. f(2) >= f(3)) then
            mx%t_us = [mx%t_us, t(2)];  mx%f_n = [mx%f_n, f(2)]
         end if
      end do
      close (u)
      if (size(mx%f_n) == 0) return
      mx%t_us = pack(mx%t_us, mx%f_n >= kept_fraction*maxval(mx%f_n))
      mx%f_n = pack(mx%f_n, mx%f_n >= kept_fraction*maxval(mx%f_n))
   end subroutine force_maxima

end module history_reader
