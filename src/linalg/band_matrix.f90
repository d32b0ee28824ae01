!> Symmetric positive definite band matrix in LAPACK's upper band storage,
!> factored in place by Cholesky (dpbtrf, dpbtrs; dsbmv for products): one
!> of the storages of the global matrices (src/linalg/global_matrix.f90)
!> that solve the linear system of eq. (19). The storage scheme and the
!> pivot rule: the comment above band_matrix_t.
module band_matrix
   use kinds, only: dp, msg_len
   use number_text, only: int_str
   use, intrinsic :: iso_fortran_env, only: int64
   implicit none
   private
   public :: band_matrix_t, check_pivot, check_pivots
   public :: band_init, band_in_band, band_add, band_matvec, band_factor, band_solve, band_axpy

   !> Relative pivot tolerance: pivot d_j <= pivot_rel_tol*|A(j,j)| fails
   !> (64 machine epsilons, about 1.4e-14: all digits of d_j lost).
   real(dp), parameter :: pivot_rel_tol = 64 * epsilon(1.0_dp)

   !> Storage scheme (the only place it is documented)
   !> ------------------------------------------------
   !> A symmetric matrix A of order n with half-bandwidth kd (A(i,j) = 0 when
   !> |i - j| > kd) keeps only its upper triangle inside the band, column by
   !> column, in the array ab(kd+1, n):
   !>
   !>     ab(kd+1+i-j, j) = A(i,j)    for  max(1, j-kd) <= i <= j
   !>
   !> so the diagonal is the last row of ab and the k-th superdiagonal is row
   !> kd+1-k. Example, n = 5, kd = 2:
   !>
   !>          A (upper triangle)               ab (kd+1 = 3 rows, n = 5 columns)
   !>     | a11 a12 a13  .   .  |         row 1:   *    *   a13  a24  a35
   !>     |     a22 a23 a24  .  |         row 2:   *   a12  a23  a34  a45
   !>     |         a33 a34 a35 |         row 3:  a11  a22  a33  a44  a55  <- diagonal
   !>     |             a44 a45 |
   !>     | sym             a55 |         (* = unused, kept zero)
   !>
   !> A(i,j) and A(j,i) are one stored number (band_add mirrors i > j): an
   !> assembly adds each global pair once (global_assemble: row <= column).
   !>
   !> This layout is what LAPACK dpbtrf/dpbtrs and BLAS dsbmv read with
   !> uplo = 'U' and ldab = kd+1. band_factor overwrites ab in place with the
   !> Cholesky factor U (A = U^T U, same layout); afterwards the matrix can
   !> only be solved with, not added into or multiplied with, until band_zero.
   !>
   !> Pivot rule (check_pivot, the same for every storage): equation j fails when its pivot
   !> d_j = U(j,j)**2 is not greater than pivot_rel_tol * |A(j,j)|, A(j,j) before
   !> factorisation: negative, zero and rounding-zero pivots (an unrestrained rigid-body mode).
   type :: band_matrix_t
      integer :: n = 0  !< order of the matrix (number of equations).
      integer :: kd = 0  !< half-bandwidth: A(i,j) = 0 for |i-j| > kd.
      real(dp), allocatable :: ab(:,:)  !< band of the upper triangle, ab(kd+1+i-j, j) = A(i,j).
      logical :: factored = .false.  !< true once ab holds the Cholesky factor instead of A.
   end type band_matrix_t

   ! LAPACK and BLAS routines, double precision, called with uplo = 'U'.
   interface
      subroutine dpbtrf(uplo, n, kd, ab, ldab, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, kd, ldab
         real(dp), intent(inout) :: ab(ldab, *)
         integer, intent(out) :: info
      end subroutine dpbtrf
      subroutine dpbtrs(uplo, n, kd, nrhs, ab, ldab, b, ldb, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, kd, nrhs, ldab, ldb
         real(dp), intent(in) :: ab(ldab, *)
         real(dp), intent(inout) :: b(ldb, *)
         integer, intent(out) :: info
      end subroutine dpbtrs
      subroutine dsbmv(uplo, n, k, alpha, a, lda, x, incx, beta, y, incy)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, k, lda, incx, incy
         real(dp), intent(in) :: alpha, beta
         real(dp), intent(in) :: a(lda, *), x(*)
         real(dp), intent(inout) :: y(*)
      end subroutine dsbmv
   end interface

contains

   !> Allocate an n x n band matrix of half-bandwidth kd, all zero.
   subroutine band_init(a, n, kd, stat, errmsg)
      type(band_matrix_t), intent(out) :: a  !< the matrix, (re)defined here.
      integer, intent(in) :: n  !< order of the matrix, n >= 1.
      integer, intent(in) :: kd  !< half-bandwidth, 0 <= kd <= n-1.
      integer, intent(out) :: stat  !< 0 on success, 1 on invalid sizes or failed allocation.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      character(len=msg_len) :: msg
      stat = 1
      if (n < 1 .or. kd < 0 .or. kd > n - 1) then
         write (msg, '(a,i0,a,i0,a)') 'band_init: invalid order n = ', n, &
            ' or half-bandwidth kd = ', kd, ' (need n >= 1, 0 <= kd <= n-1)'
      else if (int(kd + 1, int64) * int(n, int64) > int(huge(n), int64)) then
         write (msg, '(a,i0,a,i0,a)') 'band_init: band of ', kd + 1, ' x ', n, &
            ' entries exceeds the default integer range'
      else
         allocate (a%ab(kd + 1, n), source=0.0_dp, stat=stat)  ! (gfortran 12's errmsg= misleads)
         if (stat /= 0) write (msg, '(a,i0,a,i0,a,i0,a)') 'band_init: out of memory: the band matrix of ', &
            kd + 1, ' x ', n, ' reals (', (int(kd + 1, int64)*int(n, int64)*8_int64)/1048576_int64, &
            ' MiB) cannot be allocated'
      end if
      if (stat /= 0) then
         stat = 1
         errmsg = msg
         return
      end if
      a%n = n
      a%kd = kd
   end subroutine band_init

   !> True when A(i,j) is a valid index pair inside the stored band.
   pure logical function band_in_band(a, i, j)
      type(band_matrix_t), intent(in) :: a  !< the matrix.
      integer, intent(in) :: i, j      !< row and column indices
      band_in_band = i >= 1 .and. i <= a%n .and. j >= 1 .and. j <= a%n &
                     .and. abs(i - j) <= a%kd
   end function band_in_band

   !> Add value to A(i,j) (= A(j,i), one stored entry); a pair outside the
   !> band is not stored (global_matrix checks before it adds).
   subroutine band_add(a, i, j, value)
      type(band_matrix_t), intent(inout) :: a  !< the matrix, added into.
      integer, intent(in) :: i, j      !< row and column indices
      real(dp), intent(in) :: value  !< value added to A(i,j).
      if (band_in_band(a, i, j)) a%ab(a%kd + 1 - abs(i - j), max(i, j)) = &
         a%ab(a%kd + 1 - abs(i - j), max(i, j)) + value
   end subroutine band_add

   !> y = A x (BLAS dsbmv), a not factored and x, y of its size (global_matvec,
   !> the one caller, checks both).
   subroutine band_matvec(a, x, y)
      type(band_matrix_t), intent(in) :: a  !< the matrix, not factored
      real(dp), intent(in) :: x(:)          !< vector of length n
      real(dp), intent(out) :: y(:)         !< result A x, length n
      call dsbmv('U', a%n, a%kd, 1.0_dp, a%ab, a%kd + 1, x, 1, 0.0_dp, y, 1)
   end subroutine band_matvec

   !> Cholesky factorisation in place (LAPACK dpbtrf), A = U^T U, of a matrix
   !> not yet factored (global_factor checks). On a failed pivot stat = 1,
   !> bad_eq its equation; the matrix is left unusable.
   subroutine band_factor(a, stat, errmsg, bad_eq)
      type(band_matrix_t), intent(inout) :: a  !< the matrix, overwritten by its Cholesky factor.
      integer, intent(out) :: stat  !< 0 on success, 1 on failure.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      integer, intent(out) :: bad_eq  !< equation whose pivot failed, 0 if none did.
      real(dp), allocatable :: diag(:)
      integer :: info, j, last
      stat = 0
      bad_eq = 0
      allocate (diag, source=a%ab(a%kd + 1, :))
      call dpbtrf('U', a%n, a%kd, a%ab, a%kd + 1, info)
      if (info < 0) then
         stat = 1
         errmsg = 'band_factor: dpbtrf rejected argument ' // int_str(-info)
         return
      end if
      ! dpbtrf stops only at a pivot <= 0 (equation info > 0); a tiny
      ! positive pivot before it (rounding) passes and spoils the rest.
      last = merge(info - 1, a%n, info > 0)
      call check_pivots([(j, j = 1, last)], a%ab(a%kd + 1, :last)**2, diag, info, stat, errmsg, bad_eq)
      a%factored = stat == 0
   end subroutine band_factor

   !> Solve A x = b with the factor (dpbtrs), b of length n (global_solve
   !> checks); b is overwritten with the solution.
   subroutine band_solve(a, b, stat, errmsg)
      type(band_matrix_t), intent(in) :: a  !< the factored matrix.
      real(dp), intent(inout) :: b(:)  !< right-hand side on entry, solution on return, length n.
      integer, intent(out) :: stat  !< 0 on success, 1 on failure.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      integer :: info
      stat = 1
      if (.not. a%factored) then
         errmsg = 'band_solve: the matrix is not factored (call band_factor first)'
         return
      end if
      call dpbtrs('U', a%n, a%kd, 1, a%ab, a%kd + 1, b, a%n, info)
      stat = merge(0, 1, info == 0)
      if (info /= 0) errmsg = 'band_solve: dpbtrs rejected argument ' // int_str(-info)
   end subroutine band_solve

   !> a = a + alpha*b for two unfactored matrices (global_axpy_matrix
   !> checks) of the same n and kd.
   subroutine band_axpy(a, alpha, b, stat, errmsg)
      type(band_matrix_t), intent(inout) :: a  !< the matrix added into.
      real(dp), intent(in) :: alpha  !< scalar multiplying b.
      type(band_matrix_t), intent(in) :: b  !< the matrix added, same n and kd as a.
      integer, intent(out) :: stat  !< 0 on success, 1 on failure (a unchanged).
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      stat = 0
      if (a%n /= b%n .or. a%kd /= b%kd) then        ! (both initialised: global_axpy_matrix checks)
         stat = 1
         errmsg = 'band_axpy: structures differ (n = ' // int_str(a%n) // ', kd = ' // int_str(a%kd) // ' against n = ' &
            // int_str(b%n) // ', kd = ' // int_str(b%kd) // ')'
         return
      end if
      a%ab = a%ab + alpha * b%ab
   end subroutine band_axpy

   !> The pivot rule (above band_matrix_t) at equation j: stat = 1, bad_eq = j
   !> and the message when the pivot d_j is not greater than pivot_rel_tol
   !> |A(j,j)| (NaN fails too), else stat = 0 and bad_eq = 0.
   pure subroutine check_pivot(j, pivot, ajj, stat, errmsg, bad_eq)
      integer, intent(in) :: j                    !< the equation
      real(dp), intent(in) :: pivot               !< its pivot d_j
      real(dp), intent(in) :: ajj                 !< A(j,j) before the factorization
      integer, intent(out) :: stat                !< 0: the pivot passes
      character(len=*), intent(inout) :: errmsg   !< the reason, on failure
      integer, intent(out) :: bad_eq              !< j when the pivot fails, else 0
      character(len=msg_len) :: msg
      stat = 0
      bad_eq = 0
      if (pivot > pivot_rel_tol * abs(ajj)) return
      stat = 1
      bad_eq = j
      write (msg, '(a,i0,a,es10.3,a,es9.2,a,es10.3,a)') 'matrix not positive definite at equation ', j, &
         ' (pivot ', pivot, ' <= ', pivot_rel_tol, ' x diagonal ', ajj, ')'
      errmsg = msg
   end subroutine check_pivot

   !> The pivot rule on the pivots of the equations eqs, in the order of elimination, then the
   !> equation `stopped` at which the factorization met a pivot <= 0 (0: none): the first that
   !> fails gives stat = 1, bad_eq and the message (band, and sparse_matrix's CHOLMOD factor).
   pure subroutine check_pivots(eqs, pivots, diag, stopped, stat, errmsg, bad_eq)
      integer, intent(in) :: eqs(:)               !< the equations, in the order of elimination
      real(dp), intent(in) :: pivots(:)           !< their pivots d_j
      real(dp), intent(in) :: diag(:)             !< A(j,j) before the factorization, by equation
      integer, intent(in) :: stopped              !< equation of a pivot <= 0 that stopped it, 0: none
      integer, intent(out) :: stat                !< 0: every pivot passes
      character(len=*), intent(inout) :: errmsg   !< the reason, on failure
      integer, intent(out) :: bad_eq              !< equation whose pivot failed, 0 if none did
      character(len=msg_len) :: msg
      integer :: k
      stat = 0
      bad_eq = 0
      do k = 1, size(eqs)
         call check_pivot(eqs(k), pivots(k), diag(eqs(k)), stat, errmsg, bad_eq)
         if (stat /= 0) return
      end do
      if (stopped == 0) return
      stat = 1
      bad_eq = stopped
      write (msg, '(a,i0,a,es10.3,a)') 'matrix not positive definite at equation ', &
         stopped, ' (pivot <= 0, diagonal ', diag(stopped), ')'
      errmsg = msg
   end subroutine check_pivots

end module band_matrix
