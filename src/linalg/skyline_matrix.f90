!> Symmetric matrix in active-column (skyline) storage, with the in-place
!> L D L^T factorisation and solution of Bathe's COLSOL, written out from the
!> mathematics for teaching: a storage of global_matrix for eq. (19). The
!> storage scheme: the comment above skyline_matrix_t.
module skyline_matrix
   use kinds, only: dp, msg_len
   use band_matrix, only: check_pivot
   use, intrinsic :: iso_fortran_env, only: int64
   implicit none
   private
   public :: skyline_matrix_t
   public :: skyline_init, skyline_in_profile, skyline_add, &
             skyline_half_bandwidth, skyline_matvec, skyline_factor, skyline_solve, skyline_axpy

   !> Storage scheme (the only place it is documented)
   !> ------------------------------------------------
   !> Only the upper triangle is kept. Column j is stored from its diagonal
   !> UP to its first nonzero row m_j = first_row(j), consecutively, in one
   !> packed array a(1:nwk); maxa(j) is the address of the diagonal A(j,j), and
   !> maxa(n+1) = nwk + 1 closes the last column (Bathe's convention):
   !>
   !>     a(maxa(j) + j - i) = A(i,j)      for  m_j <= i <= j
   !>     column height  j - m_j = maxa(j+1) - maxa(j) - 1   (off-diagonals)
   !>     nwk = maxa(n+1) - 1                                (stored reals)
   !>
   !> Worked example, n = 5 (. = zero outside the profile, not stored;
   !> 0 = zero inside the profile, stored, may fill in during factorisation):
   !>
   !>          col:  1    2    3    4    5        first_row m_j = 1 1 2 1 4
   !>     row 1  | a11  a12   .   a14   .  |
   !>     row 2  |      a22  a23   0    .  |
   !>     row 3  |           a33  a34   .  |
   !>     row 4  |                a44  a45 |
   !>     row 5  | sym                 a55 |
   !>
   !>     address  1  |  2   3  |  4   5  |  6   7   8   9  | 10  11
   !>     a      = a11| a22 a12 | a33 a23 | a44 a34  0  a14 | a55 a45
   !>     maxa   = 1, 2, 4, 6, 10, 12          nwk = 11
   !>
   !> e.g. A(1,4) is at maxa(4) + 4 - 1 = 9, A(4,5) at maxa(5) + 5 - 4 = 11.
   !> A(i,j) and A(j,i) are one stored number (skyline_add mirrors i > j).
   !>
   !> After skyline_factor the same addresses hold A = L D L^T (L unit lower triangular, D
   !> diagonal): a(maxa(j)) = d_j and a(maxa(j) + j - i) = l_ij, meaning L(j,i), for
   !> m_j <= i < j. L has the profile of A (no fill-in outside it), which is why the profile is
   !> the storage. The pivot rule: band_matrix's check_pivot on d_j.
   type :: skyline_matrix_t
      integer :: n = 0  !< order of the matrix (number of equations).
      integer, allocatable :: maxa(:)  !< address of the diagonal of column j in a; maxa(n+1) = nwk + 1.
      real(dp), allocatable :: a(:)  !< packed columns, a(maxa(j) + j - i) = A(i,j).
      logical :: factored = .false.  !< true once a holds L and D instead of A.
   end type skyline_matrix_t

contains

   !> Build the addresses from the profile and allocate a zero matrix.
   subroutine skyline_init(sky, n, first_row, stat, errmsg)
      type(skyline_matrix_t), intent(out) :: sky  !< the matrix, (re)defined here.
      integer, intent(in) :: n  !< order of the matrix, n >= 1.
      integer, intent(in) :: first_row(:)  !< first_row(j): smallest row with a nonzero in column j, 1..j.
      integer, intent(out) :: stat  !< 0 on success, 1 on invalid input or failed allocation.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      character(len=msg_len) :: msg
      integer(int64) :: nwk
      integer :: j, k
      stat = 1
      if (n < 1 .or. size(first_row) /= n) then
         write (msg, '(a,i0,a,i0)') 'skyline_init: order n = ', n, ' with size(first_row) = ', size(first_row)
      else if (any(first_row < 1 .or. first_row > [(k, k = 1, n)])) then
         j = findloc(first_row < 1 .or. first_row > [(k, k = 1, n)], .true., dim=1)
         write (msg, '(a,i0,a,i0,a)') 'skyline_init: first_row(', j, ') = ', first_row(j), ' is outside 1..j'
      else
         nwk = sum(int([(k - first_row(k) + 1, k = 1, n)], int64))
         if (nwk >= int(huge(n), int64)) then
            write (msg, '(a,i0,a)') 'skyline_init: profile of ', nwk, ' entries exceeds the default integer range'
         else
            allocate (sky%maxa(n + 1), sky%a(nwk), stat=stat, errmsg=msg)
            if (stat /= 0) msg = 'skyline_init: allocation failed: ' // trim(msg)
         end if
      end if
      if (stat /= 0) then
         stat = 1
         errmsg = msg
         return
      end if
      ! maxa(j+1) = maxa(j) + (column height j - m_j) + 1 (the diagonal).
      sky%maxa(1) = 1
      do j = 1, n
         sky%maxa(j + 1) = sky%maxa(j) + j - first_row(j) + 1
      end do
      sky%n = n
      sky%a = 0.0_dp
   end subroutine skyline_init

   !> First stored row m_j of column j.
   pure integer function skyline_first_row(sky, j)
      type(skyline_matrix_t), intent(in) :: sky  !< the matrix.
      integer, intent(in) :: j  !< column, 1..n.
      skyline_first_row = j - (sky%maxa(j + 1) - sky%maxa(j) - 1)
   end function skyline_first_row

   !> Largest column height max_j (j - m_j): the half-bandwidth a band
   !> storage of the same matrix would need.
   pure integer function skyline_half_bandwidth(sky)
      type(skyline_matrix_t), intent(in) :: sky  !< the matrix, initialised.
      skyline_half_bandwidth = maxval(sky%maxa(2:) - sky%maxa(:sky%n)) - 1
   end function skyline_half_bandwidth

   !> True when A(i,j) is a valid index pair inside the stored profile.
   pure logical function skyline_in_profile(sky, i, j)
      type(skyline_matrix_t), intent(in) :: sky  !< the matrix.
      integer, intent(in) :: i, j      !< row and column indices
      skyline_in_profile = .false.
      if (min(i, j) < 1 .or. max(i, j) > sky%n) return
      skyline_in_profile = min(i, j) >= skyline_first_row(sky, max(i, j))
   end function skyline_in_profile

   !> Add value to A(i,j) (= A(j,i), one stored entry); a pair outside the
   !> profile is not stored (global_matrix checks before it adds).
   subroutine skyline_add(sky, i, j, value)
      type(skyline_matrix_t), intent(inout) :: sky  !< the matrix, added into.
      integer, intent(in) :: i, j      !< row and column indices
      real(dp), intent(in) :: value  !< value added to A(i,j).
      if (skyline_in_profile(sky, i, j)) sky%a(sky%maxa(max(i, j)) + abs(i - j)) = &
         sky%a(sky%maxa(max(i, j)) + abs(i - j)) + value
   end subroutine skyline_add

   !> y = A x, column by column over the stored upper triangle; sky not factored and x, y of
   !> its size (global_matvec, the one caller, checks both).
   subroutine skyline_matvec(sky, x, y)
      type(skyline_matrix_t), intent(in) :: sky  !< the matrix, not factored
      real(dp), intent(in) :: x(:)               !< vector of length n
      real(dp), intent(out) :: y(:)              !< result A x, length n
      real(dp) :: aij
      integer :: i, j
      ! Each stored A(i,j), i < j, acts twice: y_i += A(i,j) x_j and
      ! y_j += A(j,i) x_i; the diagonal once, first.
      y = sky%a(sky%maxa(:sky%n)) * x
      do j = 1, sky%n
         do i = skyline_first_row(sky, j), j - 1
            aij = sky%a(sky%maxa(j) + j - i)
            y(i) = y(i) + aij * x(j)
            y(j) = y(j) + aij * x(i)
         end do
      end do
   end subroutine skyline_matvec

   !> In-place L D L^T factorisation, column by column (COLSOL's algorithm), of
   !> a matrix not yet factored (global_factor checks). On a failed pivot
   !> stat = 1, bad_eq its equation; the matrix is left unusable.
   subroutine skyline_factor(sky, stat, errmsg, bad_eq)
      type(skyline_matrix_t), intent(inout) :: sky  !< the matrix, overwritten by L (off-diagonals) and D (diagonal).
      integer, intent(out) :: stat  !< 0 on success, 1 on failure.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      integer, intent(out) :: bad_eq  !< equation whose pivot failed, 0 if none did.
      real(dp) :: ajj, g, l, s
      integer :: i, j, r, mi, mj
      stat = 0
      bad_eq = 0
      ! Address of A(i,j) (and later of l_ij): maxa(j) + j - i.
      columns: do j = 1, sky%n
         mj = skyline_first_row(sky, j)
         ajj = sky%a(sky%maxa(j))

         ! Phase 1 - reduce the column with the finished columns i < j:
         !    g_ij = a_ij - sum_{r = max(m_i, m_j)}^{i-1} l_ri g_rj,
         !    i = m_j+1, ..., j-1   (g_{m_j j} = a_{m_j j}),
         ! top down, so every g_rj on the right is already reduced.
         reduce: do i = mj + 1, j - 1
            mi = skyline_first_row(sky, i)
            s = 0.0_dp
            do r = max(mi, mj), i - 1
               s = s + sky%a(sky%maxa(i) + i - r) * sky%a(sky%maxa(j) + j - r)
            end do
            sky%a(sky%maxa(j) + j - i) = sky%a(sky%maxa(j) + j - i) - s
         end do reduce

         ! Phase 2 - scale by the pivots and form the new pivot:
         !    l_ij = g_ij / d_i,                 i = m_j, ..., j-1
         !    d_j  = a_jj - sum_{i=m_j}^{j-1} l_ij g_ij
         s = 0.0_dp
         scale: do i = mj, j - 1
            g = sky%a(sky%maxa(j) + j - i)
            l = g / sky%a(sky%maxa(i))
            s = s + l * g
            sky%a(sky%maxa(j) + j - i) = l
         end do scale
         sky%a(sky%maxa(j)) = ajj - s

         ! Phase 3 - the pivot rule on d_j.
         call check_pivot(j, sky%a(sky%maxa(j)), ajj, stat, errmsg, bad_eq)
         if (stat /= 0) return
      end do columns
      sky%factored = .true.
   end subroutine skyline_factor

   !> Solve A x = b with the factors L and D (b overwritten by x), sky
   !> factored and b of its size (global_solve, the one caller, checks both).
   subroutine skyline_solve(sky, b)
      type(skyline_matrix_t), intent(in) :: sky  !< the factored matrix.
      real(dp), intent(inout) :: b(:)  !< right-hand side on entry, solution on return, length n.
      integer :: i, j
      ! Forward reduction, L y = b:
      !    y_j = b_j - sum_{i=m_j}^{j-1} l_ij y_i      (a dot product with column j)
      forward: do j = 2, sky%n
         do i = skyline_first_row(sky, j), j - 1
            b(j) = b(j) - sky%a(sky%maxa(j) + j - i) * b(i)
         end do
      end do forward

      ! Diagonal scaling, D z = y:   z_j = y_j / d_j
      b = b / sky%a(sky%maxa(1:sky%n))

      ! Back substitution, L^T x = z, last column first: x_j = z_j is final
      ! once columns j+1..n are done; then remove it from the rows above,
      !    z_i = z_i - l_ij x_j,       i = m_j, ..., j-1
      back: do j = sky%n, 2, -1
         do i = skyline_first_row(sky, j), j - 1
            b(i) = b(i) - sky%a(sky%maxa(j) + j - i) * b(j)
         end do
      end do back
   end subroutine skyline_solve

   !> sky = sky + alpha*other for two unfactored matrices (global_axpy_matrix
   !> checks) of one profile.
   subroutine skyline_axpy(sky, alpha, other, stat, errmsg)
      type(skyline_matrix_t), intent(inout) :: sky  !< the matrix added into.
      real(dp), intent(in) :: alpha  !< scalar multiplying other.
      type(skyline_matrix_t), intent(in) :: other  !< the matrix added, same profile as sky.
      integer, intent(out) :: stat  !< 0 on success, 1 on failure (sky unchanged).
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      stat = 1
      if (sky%n /= other%n) then                    ! (both initialised: global_axpy_matrix checks)
         errmsg = 'skyline_axpy: the matrices differ in order'
      else if (any(sky%maxa /= other%maxa)) then
         errmsg = 'skyline_axpy: the matrices differ in profile'
      else
         stat = 0
         sky%a = sky%a + alpha * other%a
      end if
   end subroutine skyline_axpy

end module skyline_matrix
