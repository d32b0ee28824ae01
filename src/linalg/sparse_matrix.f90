!> Symmetric positive definite matrix in compressed sparse columns, factored
!> by CHOLMOD's supernodal Cholesky (cholmod_binding): a storage of
!> global_matrix for eq. (19). The scheme, the factorization and its owner:
!> the comment above sparse_matrix_t. More: docs/PERFORMANCE.md.
module sparse_matrix
   use, intrinsic :: iso_c_binding, only: c_long_long, c_int
   use, intrinsic :: iso_fortran_env, only: int64
   use kinds, only: dp, msg_len
   use band_matrix, only: check_pivots
   use cholmod_binding, only: cholmod_handle_t, chol_check, no_memory, chol_new, chol_free, chol_copy, &
                              chol_set_matrix, chol_analyze, chol_factorize, chol_diagonal, chol_solve
   use system_limits, only: physical_memory
   implicit none
   private
   public :: sparse_matrix_t
   public :: sparse_init, sparse_zero, sparse_in_pattern, sparse_add, sparse_matvec, &
             sparse_axpy, sparse_factor, sparse_solve, sparse_half_bandwidth, sparse_entries, sparse_release, &
             sparse_copy_factor

   !> Bytes in a GiB, for the messages.
   real(dp), parameter :: gib = 1024.0_dp**3

   !> Storage scheme (the only place it is documented)
   !> ------------------------------------------------
   !> Only the upper triangle is kept, and in it only the pairs (i, j), i <= j, that some
   !> element couples (both equations are freedoms of one element; the diagonal always).
   !> Column j holds its rows ascending, the diagonal last, in the packed arrays rowind and val:
   !>
   !>     val(p) = A(rowind(p), j)    for  colptr(j) <= p < colptr(j+1)
   !>     nnz = colptr(n+1) - 1       (stored reals)
   !>
   !> Example, n = 5, elements holding equations {1, 2, 4} and {3, 4, 5}:
   !>
   !>          col:  1    2    3    4    5
   !>     row 1  | a11  a12   .   a14   .  |      colptr = 1, 2, 4, 5, 9, 12
   !>     row 2  |      a22   .   a24   .  |      rowind = 1 | 1 2 | 3 | 1 2 3 4 | 3 4 5
   !>     row 3  |           a33  a34  a35 |      val    = a11 | a12 a22 | a33 |
   !>     row 4  |                a44  a45 |               a14 a24 a34 a44 | a35 a45 a55
   !>     row 5  | sym                 a55 |
   !>
   !> The pattern comes from the element freedom table alone (sparse_init), so M, K_L and
   !> K_L + 4/dt^2 M of one model share it. A(i,j) and A(j,i) are one stored number (sparse_add
   !> mirrors i > j). For a plate this keeps about 40 reals per equation where band storage
   !> keeps kd + 1 (hundreds to thousands).
   !>
   !> Factorization: CHOLMOD orders the equations to reduce the fill (AMD, or METIS), analyses
   !> the factor's structure once per pattern (kept: a refactorization after sparse_zero costs
   !> only the numbers), checks its size against the machine's memory, and computes
   !> P A P^T = L L^T with dense BLAS; the values of A are then released. The factor lives in
   !> CHOLMOD's memory until sparse_release; b = a shares it, sparse_copy_factor copies it. The
   !> pivot rule (band_matrix's check_pivot) on d_j = L(k,k)**2 in the order of elimination:
   !> for a mechanism the equation named may be another of the same mechanism than band's.
   type :: sparse_matrix_t
      integer :: n = 0  !< order of the matrix (number of equations).
      integer(c_long_long), allocatable :: colptr(:)  !< start of column j in rowind and val, colptr(n+1) = nnz + 1.
      integer, allocatable :: rowind(:)  !< rows of the stored entries, ascending in each column.
      real(dp), allocatable :: val(:)  !< values, val(p) = A(rowind(p), j); released once factored.
      logical :: factored = .false.  !< true once the handle holds the numeric factor (and val is gone).
      logical :: analysed = .false.  !< true once the handle holds the symbolic factorization of the pattern.
      real(dp) :: factor_entries = 0.0_dp  !< nonzeros of L, from the analysis.
      real(dp) :: factor_bytes = 0.0_dp  !< memory of the numeric factor, from the analysis (bytes).
      type(cholmod_handle_t) :: chol  !< CHOLMOD's factorization (symbolic, then numeric).
   end type sparse_matrix_t

contains

   !> The pattern of the element freedom table (above sparse_matrix_t) and a zero matrix on it.
   subroutine sparse_init(a, n, elem_eq, stat, errmsg)
      type(sparse_matrix_t), intent(out) :: a  !< the matrix, (re)defined here.
      integer, intent(in) :: n  !< order of the matrix, n >= 1.
      integer, intent(in) :: elem_eq(:,:)  !< elem_eq(k, e): equation of freedom k of element e, 0 = none; in 0..n.
      integer, intent(out) :: stat  !< 0 on success, 1 on a failed allocation.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      integer, allocatable :: first(:), elems(:)
      integer(c_long_long), allocatable :: next(:)
      character(len=msg_len) :: msg
      integer :: j
      call equation_elements(n, elem_eq, first, elems)
      allocate (a%colptr(n + 1), next(n), stat=stat, errmsg=msg)
      if (stat == 0) then
         ! pass 1: entries per column; pass 2: their rows, ascending because
         ! the rows are visited in order
         call visit_pattern(n, elem_eq, first, elems, next)
         a%colptr(1) = 1
         do j = 1, n
            a%colptr(j + 1) = a%colptr(j) + next(j)
         end do
         allocate (a%rowind(a%colptr(n + 1) - 1), a%val(a%colptr(n + 1) - 1), stat=stat, errmsg=msg)
      end if
      if (stat /= 0) then
         stat = 1
         errmsg = 'sparse_init: allocation of the pattern failed: ' // trim(msg)
         return
      end if
      next = a%colptr(:n)
      call visit_pattern(n, elem_eq, first, elems, next, a%rowind)
      a%val = 0.0_dp
      a%n = n
   end subroutine sparse_init

   !> Every pair (i, j), i <= j, that an element couples (and every
   !> diagonal), row by row: without rowind counted in next(j); with it, its
   !> row stored at rowind(next(j)), next(j) advanced.
   subroutine visit_pattern(n, elem_eq, first, elems, next, rowind)
      integer, intent(in) :: n  !< number of equations.
      integer, intent(in) :: elem_eq(:,:)  !< element freedom table, entries in 0..n.
      integer, intent(in) :: first(:)  !< (n+1) start of each equation's elements in elems.
      integer, intent(in) :: elems(:)  !< the elements of each equation.
      integer(c_long_long), intent(inout) :: next(:)  !< (n) count, or next free place, of each column.
      integer, intent(inout), optional :: rowind(:)  !< the rows, stored when present.
      integer, allocatable :: mark(:)
      integer :: i, j, k, p
      allocate (mark(n), source=0)
      if (.not. present(rowind)) next = 0
      rows: do i = 1, n
         call visit(i)               ! the diagonal, even of a freedom no element holds
         do p = first(i), first(i + 1) - 1
            do k = 1, size(elem_eq, 1)
               j = elem_eq(k, elems(p))
               if (j >= i) call visit(j)
            end do
         end do
      end do rows

   contains

      !> The pair (i, j), once.
      subroutine visit(col)
         integer, intent(in) :: col  !< its column j.
         if (mark(col) == i) return
         mark(col) = i
         if (present(rowind)) rowind(next(col)) = i
         next(col) = next(col) + 1
      end subroutine visit

   end subroutine visit_pattern

   !> The elements of each equation: elems(first(i) : first(i+1) - 1).
   subroutine equation_elements(n, elem_eq, first, elems)
      integer, intent(in) :: n  !< number of equations.
      integer, intent(in) :: elem_eq(:,:)  !< element freedom table, entries in 0..n.
      integer, allocatable, intent(out) :: first(:)  !< (n+1) start of each equation's elements.
      integer, allocatable, intent(out) :: elems(:)  !< the elements, equation by equation.
      integer, allocatable :: fill(:)
      integer :: e, k, eq
      allocate (first(n + 1), source=0)
      do e = 1, size(elem_eq, 2)
         do k = 1, size(elem_eq, 1)
            eq = elem_eq(k, e)
            if (eq > 0) first(eq + 1) = first(eq + 1) + 1
         end do
      end do
      first(1) = 1
      do eq = 1, n
         first(eq + 1) = first(eq + 1) + first(eq)
      end do
      allocate (elems(first(n + 1) - 1))
      fill = first(:n)
      do e = 1, size(elem_eq, 2)
         do k = 1, size(elem_eq, 1)
            eq = elem_eq(k, e)
            if (eq == 0) cycle
            elems(fill(eq)) = e
            fill(eq) = fill(eq) + 1
         end do
      end do
   end subroutine equation_elements

   !> Set every entry to zero and forget the numeric factor; the pattern and
   !> its symbolic factorization are kept.
   subroutine sparse_zero(a)
      type(sparse_matrix_t), intent(inout) :: a  !< the matrix.
      if (.not. allocated(a%colptr)) return
      if (.not. allocated(a%val)) allocate (a%val(a%colptr(a%n + 1) - 1))
      a%val = 0.0_dp
      a%factored = .false.
   end subroutine sparse_zero

   !> Release CHOLMOD's factorization (numeric and symbolic); the matrix
   !> keeps its pattern and, unless it was factored, its values.
   subroutine sparse_release(a)
      type(sparse_matrix_t), intent(inout) :: a  !< the matrix.
      call chol_free(a%chol%key)
      a%chol%key = 0
      a%analysed = .false.
      a%factored = .false.
   end subroutine sparse_release

   !> After b = a (which shares a's factorization): b's own copy of it (on
   !> failure none: b neither analysed nor factored).
   subroutine sparse_copy_factor(a, b, stat, errmsg)
      type(sparse_matrix_t), intent(in) :: a  !< the matrix copied.
      type(sparse_matrix_t), intent(inout) :: b  !< the copy, b = a done.
      integer, intent(out) :: stat  !< 0 on success, 1 on failure.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      b%chol%key = 0
      stat = 0
      if (a%chol%key /= 0) call chol_check(chol_copy(a%chol%key, b%chol%key), &
         'copying the factorization', stat, errmsg)
      b%analysed = b%analysed .and. stat == 0
      b%factored = b%factored .and. stat == 0
   end subroutine sparse_copy_factor

   !> Position of A(i,j) in rowind and val, 0 when the pattern lacks it.
   pure integer(int64) function locate(a, i, j) result(pos)
      type(sparse_matrix_t), intent(in) :: a  !< the matrix.
      integer, intent(in) :: i, j  !< row and column indices.
      integer(int64) :: lo, hi, mid
      integer :: r
      pos = 0
      if (min(i, j) < 1 .or. max(i, j) > a%n) return
      r = min(i, j)
      lo = a%colptr(max(i, j))
      hi = a%colptr(max(i, j) + 1) - 1
      do while (lo <= hi)
         mid = (lo + hi) / 2
         if (a%rowind(mid) == r) then
            pos = mid
            return
         else if (a%rowind(mid) < r) then
            lo = mid + 1
         else
            hi = mid - 1
         end if
      end do
   end function locate

   !> True when the pattern holds A(i,j).
   pure logical function sparse_in_pattern(a, i, j)
      type(sparse_matrix_t), intent(in) :: a  !< the matrix.
      integer, intent(in) :: i, j  !< row and column indices.
      sparse_in_pattern = locate(a, i, j) > 0
   end function sparse_in_pattern

   !> Add value to A(i,j) (= A(j,i), one stored entry); a pair outside the
   !> pattern is not stored (global_matrix checks before it adds).
   subroutine sparse_add(a, i, j, value)
      type(sparse_matrix_t), intent(inout) :: a  !< the matrix, added into.
      integer, intent(in) :: i, j  !< row and column indices.
      real(dp), intent(in) :: value  !< value added to A(i,j).
      integer(int64) :: p
      p = locate(a, i, j)
      if (p > 0) a%val(p) = a%val(p) + value
   end subroutine sparse_add

   !> y = A x, a not factored and x, y of its size (global_matvec, the one
   !> caller, checks both).
   subroutine sparse_matvec(a, x, y)
      type(sparse_matrix_t), intent(in) :: a  !< the matrix, not factored.
      real(dp), intent(in) :: x(:)  !< vector of length n.
      real(dp), intent(out) :: y(:)  !< result A x, length n.
      integer(int64) :: p
      integer :: i, j
      real(dp) :: yj
      y = 0.0_dp
      do j = 1, a%n
         yj = 0.0_dp
         do p = a%colptr(j), a%colptr(j + 1) - 2        ! above the diagonal
            i = a%rowind(p)
            y(i) = y(i) + a%val(p) * x(j)
            yj = yj + a%val(p) * x(i)
         end do
         y(j) = y(j) + yj + a%val(a%colptr(j + 1) - 1) * x(j)     ! the diagonal, last
      end do
   end subroutine sparse_matvec

   !> a = a + alpha*b for two unfactored matrices of the same pattern.
   subroutine sparse_axpy(a, alpha, b, stat, errmsg)
      type(sparse_matrix_t), intent(inout) :: a  !< the matrix added into.
      real(dp), intent(in) :: alpha  !< scalar multiplying b.
      type(sparse_matrix_t), intent(in) :: b  !< the matrix added, same pattern as a.
      integer, intent(out) :: stat  !< 0 on success, 1 on failure (a unchanged).
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      stat = 1
      if (a%factored .or. b%factored .or. .not. allocated(a%val) .or. .not. allocated(b%val)) then
         errmsg = 'sparse_axpy: a factored matrix cannot be added to or from'
      else if (a%n /= b%n .or. size(a%rowind) /= size(b%rowind)) then
         errmsg = 'sparse_axpy: patterns differ (orders or numbers of entries)'
      else if (any(a%colptr /= b%colptr) .or. any(a%rowind /= b%rowind)) then
         errmsg = 'sparse_axpy: patterns differ'
      else
         stat = 0
         a%val = a%val + alpha * b%val
      end if
   end subroutine sparse_axpy

   !> Cholesky factorization by CHOLMOD (above sparse_matrix_t). On a failed
   !> pivot stat = 1, bad_eq its equation; the matrix is unusable until sparse_zero.
   subroutine sparse_factor(a, stat, errmsg, bad_eq)
      type(sparse_matrix_t), intent(inout) :: a  !< the matrix, replaced by its factor.
      integer, intent(out) :: stat  !< 0 on success, 1 on failure.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      integer, intent(out) :: bad_eq  !< equation whose pivot failed, 0 if none did.
      real(dp), allocatable :: diag(:), ldiag(:)
      integer(c_long_long), allocatable :: perm(:)
      integer(c_long_long) :: minor
      integer(c_int) :: code
      integer :: last, stopped
      stat = 0
      bad_eq = 0
      if (.not. allocated(a%val) .or. a%factored) then
         stat = 1
         errmsg = 'sparse_factor: the matrix is not initialised, or is already factored'
         return
      end if
      diag = a%val(a%colptr(2:) - 1)          ! the diagonal, last in each column
      if (a%chol%key == 0) a%chol%key = chol_new()
      code = no_memory
      if (a%chol%key /= 0) code = chol_set_matrix(a%chol%key, int(a%n, c_long_long), a%colptr, &
         a%rowind, a%val)
      call chol_check(code, 'handing the matrix over', stat, errmsg)
      if (stat /= 0) return
      if (.not. a%analysed) then
         call sparse_analyse(a, stat, errmsg)
         if (stat /= 0) return
      end if
      deallocate (a%val)        ! CHOLMOD holds the matrix now
      call chol_check(chol_factorize(a%chol%key, minor), 'the factorization', stat, errmsg)
      if (stat /= 0) return
      ! the pivot rule on L(k,k)**2, k in the order of elimination, up to CHOLMOD's stop
      allocate (ldiag(a%n), perm(a%n))
      call chol_check(chol_diagonal(a%chol%key, int(a%n, c_long_long), ldiag, perm), 'the diagonal', &
         stat, errmsg)
      if (stat /= 0) return
      last = min(int(minor) - 1, a%n)
      stopped = 0
      if (minor <= a%n) stopped = int(perm(minor))
      call check_pivots(int(perm(:last)), ldiag(:last)**2, diag, stopped, stat, errmsg, bad_eq)
      a%factored = stat == 0
   end subroutine sparse_factor

   !> The symbolic factorization of the matrix handed over, and the check of
   !> the factor's size against the machine's memory.
   subroutine sparse_analyse(a, stat, errmsg)
      type(sparse_matrix_t), intent(inout) :: a  !< the matrix, handed over to its handle.
      integer, intent(out) :: stat  !< 0 on success, 1 on failure.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      real(dp) :: flops, machine
      character(len=msg_len) :: msg
      call chol_check(chol_analyze(a%chol%key, a%factor_entries, flops, a%factor_bytes), &
         'the analysis', stat, errmsg)
      if (stat /= 0) return
      machine = physical_memory()
      if (machine > 0.0_dp .and. a%factor_bytes > machine) then
         stat = 1
         write (msg, '(a,i0,a,f0.2,a,es9.2,a,f0.2,a)') 'sparse: the factor of the ', a%n, &
            ' equations would take ', a%factor_bytes / gib, ' GiB (CHOLMOD''s analysis: ', &
            a%factor_entries, ' nonzeros), more than this machine''s ', machine / gib, &
            ' GiB: a coarser mesh, or a graded one (&mesh grading)'
         errmsg = msg
         call sparse_release(a)
         return
      end if
      a%analysed = .true.
   end subroutine sparse_analyse

   !> Solve A x = b with the factor, b of its size (global_solve, the one
   !> caller, checks both); b is overwritten by x.
   subroutine sparse_solve(a, b, stat, errmsg)
      type(sparse_matrix_t), intent(in) :: a  !< the factored matrix.
      real(dp), intent(inout) :: b(:)  !< right-hand side on entry, solution on return, length n.
      integer, intent(out) :: stat  !< 0 on success, 1 on failure.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      call chol_check(chol_solve(a%chol%key, size(b, kind=c_long_long), b), 'the solve', stat, errmsg)
   end subroutine sparse_solve

   !> Largest distance of a stored entry from the diagonal, max (j - i).
   pure integer function sparse_half_bandwidth(a)
      type(sparse_matrix_t), intent(in) :: a  !< the matrix, initialised.
      integer :: j
      sparse_half_bandwidth = maxval([(j - a%rowind(a%colptr(j)), j = 1, a%n)])
   end function sparse_half_bandwidth

   !> Number of stored entries of A (the upper triangle's pattern).
   pure integer(int64) function sparse_entries(a)
      type(sparse_matrix_t), intent(in) :: a  !< the matrix.
      sparse_entries = 0
      if (allocated(a%colptr)) sparse_entries = a%colptr(a%n + 1) - 1
   end function sparse_entries

end module sparse_matrix
