!> CHOLMOD (SuiteSparse's sparse Cholesky) for the sparse storage: bind(c)
!> interfaces to the flat C functions of cholmod_shim.c (only integers,
!> doubles and arrays cross; its header lists the return codes), and a
!> handle holding the key of one factorization in the shim's table, alive
!> until chol_release (explicit: gfortran 12 finalizes an assignment's
!> temporaries). An assignment copies the key, chol_copy the factorization.
!> Not from the paper. More: docs/PERFORMANCE.md ("Sparse storage (CHOLMOD)").
module cholmod_binding
   use, intrinsic :: iso_c_binding, only: c_int, c_long_long, c_double
   use kinds, only: dp
   use number_text, only: int_str
   implicit none
   private
   public :: cholmod_handle_t, cholmod_live_handles, chol_set_matrix, chol_analyze, chol_factorize, &
             chol_diagonal, chol_solve, chol_copy, chol_release

   !> Return codes of the shim (src/linalg/cholmod_shim.c).
   integer(c_int), parameter :: code_ok = 0, no_handle = 1, no_memory = 2, too_large = 3, invalid = 4, &
                                failed = 5

   !> One factorization (symbolic, then numeric) in the shim's table.
   type :: cholmod_handle_t
      integer(c_long_long) :: key = 0  !< key in the shim's table, 0 = none.
   end type cholmod_handle_t

   ! The shim's functions, each documented in cholmod_shim.c.
   interface
      function impact_cholmod_new() bind(c, name='impact_cholmod_new') result(key)
         import :: c_long_long
         integer(c_long_long) :: key
      end function impact_cholmod_new
      subroutine impact_cholmod_free(key) bind(c, name='impact_cholmod_free')
         import :: c_long_long
         integer(c_long_long), value :: key  !< the handle.
      end subroutine impact_cholmod_free
      function impact_cholmod_live() bind(c, name='impact_cholmod_live') result(n)
         import :: c_long_long
         integer(c_long_long) :: n
      end function impact_cholmod_live
      function impact_cholmod_status() bind(c, name='impact_cholmod_status') result(status)
         import :: c_int
         integer(c_int) :: status
      end function impact_cholmod_status
      function impact_cholmod_copy(key, copy) bind(c, name='impact_cholmod_copy') result(code)
         import :: c_long_long, c_int
         integer(c_long_long), value :: key  !< the handle copied.
         integer(c_long_long), intent(out) :: copy  !< the new handle.
         integer(c_int) :: code
      end function impact_cholmod_copy
      function impact_cholmod_set_matrix(key, n, colptr, rowind, values) &
            bind(c, name='impact_cholmod_set_matrix') result(code)
         import :: c_long_long, c_int, c_double
         integer(c_long_long), value :: key  !< the handle.
         integer(c_long_long), value :: n  !< order.
         integer(c_long_long), intent(in) :: colptr(*)  !< column starts (n+1).
         integer(c_int), intent(in) :: rowind(*)  !< rows, ascending in each column.
         real(c_double), intent(in) :: values(*)  !< values, as rowind.
         integer(c_int) :: code
      end function impact_cholmod_set_matrix
      function impact_cholmod_analyze(key, lnz, flops, bytes) bind(c, name='impact_cholmod_analyze') result(code)
         import :: c_long_long, c_int, c_double
         integer(c_long_long), value :: key  !< the handle.
         real(c_double), intent(out) :: lnz, flops, bytes  !< nnz(L), flops, bytes of the numeric factor.
         integer(c_int) :: code
      end function impact_cholmod_analyze
      function impact_cholmod_factorize(key, minor) bind(c, name='impact_cholmod_factorize') result(code)
         import :: c_long_long, c_int
         integer(c_long_long), value :: key  !< the handle.
         integer(c_long_long), intent(out) :: minor  !< 1-based failed column, n+1 if none.
         integer(c_int) :: code
      end function impact_cholmod_factorize
      function impact_cholmod_diagonal(key, n, diag, perm) bind(c, name='impact_cholmod_diagonal') result(code)
         import :: c_long_long, c_int, c_double
         integer(c_long_long), value :: key  !< the handle.
         integer(c_long_long), value :: n  !< order.
         real(c_double), intent(out) :: diag(*)  !< L(k,k), k in elimination order.
         integer(c_long_long), intent(out) :: perm(*)  !< equation eliminated k-th (1-based).
         integer(c_int) :: code
      end function impact_cholmod_diagonal
      function impact_cholmod_solve(key, n, b) bind(c, name='impact_cholmod_solve') result(code)
         import :: c_long_long, c_int, c_double
         integer(c_long_long), value :: key  !< the handle.
         integer(c_long_long), value :: n  !< order.
         real(c_double), intent(inout) :: b(*)  !< right-hand side in, solution out.
         integer(c_int) :: code
      end function impact_cholmod_solve
   end interface

contains

   !> Number of factorizations alive in the shim's table (the tests check
   !> that the matrices release theirs).
   integer function cholmod_live_handles()
      cholmod_live_handles = int(impact_cholmod_live())
   end function cholmod_live_handles

   !> Hand the matrix (upper triangle, compressed columns, 1-based; rows
   !> ascending in each column) to the handle, which is made when it has none.
   subroutine chol_set_matrix(h, colptr, rowind, values, stat, errmsg)
      type(cholmod_handle_t), intent(inout) :: h  !< the handle.
      integer(c_long_long), intent(in) :: colptr(:)  !< column starts, n+1 of them, colptr(1) = 1.
      integer(c_int), intent(in) :: rowind(:)  !< rows of the entries, colptr(n+1) - 1 of them.
      real(dp), intent(in) :: values(:)  !< values of the entries, as rowind.
      integer, intent(out) :: stat  !< 0 on success, 1 on failure.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      integer(c_int) :: code
      if (h%key == 0) h%key = impact_cholmod_new()
      code = no_memory
      if (h%key /= 0) code = impact_cholmod_set_matrix(h%key, size(colptr, kind=c_long_long) - 1, colptr, rowind, values)
      call check(code, 'handing the matrix over', stat, errmsg)
   end subroutine chol_set_matrix

   !> The symbolic factorization of the matrix handed over (fill-reducing
   !> ordering and the structure of L), before any number is computed.
   subroutine chol_analyze(h, lnz, flops, bytes, stat, errmsg)
      type(cholmod_handle_t), intent(in) :: h  !< the handle, with a matrix handed over.
      real(dp), intent(out) :: lnz  !< nonzeros of the factor L.
      real(dp), intent(out) :: flops  !< floating-point operations of the numeric factorization.
      real(dp), intent(out) :: bytes  !< memory of the numeric factor (bytes).
      integer, intent(out) :: stat  !< 0 on success, 1 on failure.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      call check(impact_cholmod_analyze(h%key, lnz, flops, bytes), 'the analysis', stat, errmsg)
   end subroutine chol_analyze

   !> The numeric factorization (supernodal L L^T) of the matrix handed over,
   !> which is released; minor: the column (order of elimination) of a pivot <= 0.
   subroutine chol_factorize(h, minor, stat, errmsg)
      type(cholmod_handle_t), intent(in) :: h  !< the handle, analysed, with a matrix handed over.
      integer, intent(out) :: minor  !< failed column in elimination order, n+1 if none.
      integer, intent(out) :: stat  !< 0 on success, 1 on failure.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      integer(c_long_long) :: m
      call check(impact_cholmod_factorize(h%key, m), 'the factorization', stat, errmsg)
      minor = int(m)
   end subroutine chol_factorize

   !> The diagonal of L, diag(k) = L(k,k), and the equation perm(k)
   !> eliminated k-th, k in the order of elimination.
   subroutine chol_diagonal(h, diag, perm, stat, errmsg)
      type(cholmod_handle_t), intent(in) :: h  !< the handle, factored (columns before minor).
      real(dp), intent(out) :: diag(:)  !< L(k,k), size n.
      integer, intent(out) :: perm(:)  !< equation eliminated k-th, size n.
      integer, intent(out) :: stat  !< 0 on success, 1 on failure.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      integer(c_long_long) :: p(size(perm))
      call check(impact_cholmod_diagonal(h%key, size(diag, kind=c_long_long), diag, p), 'the diagonal', &
                 stat, errmsg)
      perm = int(p)
   end subroutine chol_diagonal

   !> Solve A x = b with the numeric factor; b is overwritten by x.
   subroutine chol_solve(h, b, stat, errmsg)
      type(cholmod_handle_t), intent(in) :: h  !< the handle, factored.
      real(dp), intent(inout) :: b(:)  !< right-hand side on entry, solution on return.
      integer, intent(out) :: stat  !< 0 on success, 1 on failure.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      call check(impact_cholmod_solve(h%key, size(b, kind=c_long_long), b), 'the solve', stat, errmsg)
   end subroutine chol_solve

   !> dst holds a copy of src's factorization (symbolic and numeric), under
   !> a key of its own; none when src holds none.
   subroutine chol_copy(src, dst, stat, errmsg)
      type(cholmod_handle_t), intent(in) :: src  !< the handle copied.
      type(cholmod_handle_t), intent(out) :: dst  !< the copy (a handle it held before is not released).
      integer, intent(out) :: stat  !< 0 on success, 1 on failure.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      integer(c_long_long) :: copy
      stat = 0
      if (src%key == 0) return
      call check(impact_cholmod_copy(src%key, copy), 'copying the factorization', stat, errmsg)
      dst%key = copy
   end subroutine chol_copy

   !> Release the factorization the handle holds (none afterwards).
   subroutine chol_release(h)
      type(cholmod_handle_t), intent(inout) :: h  !< the handle.
      call impact_cholmod_free(h%key)
      h%key = 0
   end subroutine chol_release

   ! ---- private ---------------------------------------------------------------

   !> stat and errmsg from a return code of the shim: what it means.
   subroutine check(code, what, stat, errmsg)
      integer(c_int), intent(in) :: code  !< the return code.
      character(len=*), intent(in) :: what  !< the step, for the message.
      integer, intent(out) :: stat  !< 0 for code_ok, 1 otherwise.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      character(len=:), allocatable :: text
      stat = 0
      select case (code)
      case (code_ok); return
      case (no_handle); text = 'the factorization was released (an assigned copy used after the original''s release?)'
      case (no_memory); text = 'out of memory'
      case (too_large); text = 'the problem is too large for CHOLMOD''s integers'
      case (invalid); text = 'invalid input (no matrix handed over, or not analysed)'
      case default; text = 'CHOLMOD failed with status ' // int_str(int(impact_cholmod_status()))
      end select
      stat = 1
      errmsg = 'sparse (CHOLMOD): ' // what // ' failed: ' // text
   end subroutine check

end module cholmod_binding
