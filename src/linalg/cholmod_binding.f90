!> CHOLMOD (SuiteSparse's sparse Cholesky) for the sparse storage: bind(c)
!> interfaces to the flat C functions of cholmod_shim.c (only integers,
!> doubles and arrays cross; its header lists the return codes), and a
!> handle holding the key of one factorization in the shim's table, alive
!> until chol_free (explicit: gfortran 12 finalizes an assignment's
!> temporaries). An assignment copies the key, chol_copy the factorization;
!> chol_check turns a return code into stat and errmsg.
!> Not from the paper. More: docs/PERFORMANCE.md ("Sparse storage (CHOLMOD)").
module cholmod_binding
   use, intrinsic :: iso_c_binding, only: c_int, c_long_long, c_double
   use kinds, only: dp
   use number_text, only: int_str
   implicit none
   private
   public :: cholmod_handle_t, cholmod_live_handles, chol_check, no_memory
   public :: chol_new, chol_free, chol_copy, chol_set_matrix, chol_analyze, chol_factorize, &
             chol_diagonal, chol_solve

   !> Return codes of the shim (src/linalg/cholmod_shim.c).
   integer(c_int), parameter :: code_ok = 0, no_handle = 1, no_memory = 2, too_large = 3, invalid = 4, &
                                failed = 5

   !> One factorization (symbolic, then numeric) in the shim's table.
   type :: cholmod_handle_t
      integer(c_long_long) :: key = 0  !< key in the shim's table, 0 = none.
   end type cholmod_handle_t

   ! The shim's functions, each documented in cholmod_shim.c.
   interface
      integer(c_long_long) function chol_new() bind(c, name='impact_cholmod_new')
         import :: c_long_long
      end function chol_new
      subroutine chol_free(key) bind(c, name='impact_cholmod_free')
         import :: c_long_long
         integer(c_long_long), value :: key  !< the handle.
      end subroutine chol_free
      integer(c_long_long) function chol_live() bind(c, name='impact_cholmod_live')
         import :: c_long_long
      end function chol_live
      integer(c_int) function chol_status() bind(c, name='impact_cholmod_status')
         import :: c_int
      end function chol_status
      integer(c_int) function chol_copy(key, copy) bind(c, name='impact_cholmod_copy')
         import :: c_long_long, c_int
         integer(c_long_long), value :: key  !< the handle copied.
         integer(c_long_long), intent(out) :: copy  !< the new handle.
      end function chol_copy
      integer(c_int) function chol_set_matrix(key, n, colptr, rowind, values) &
            bind(c, name='impact_cholmod_set_matrix')
         import :: c_long_long, c_int, c_double
         integer(c_long_long), value :: key  !< the handle.
         integer(c_long_long), value :: n  !< order.
         integer(c_long_long), intent(in) :: colptr(*)  !< column starts (n+1).
         integer(c_int), intent(in) :: rowind(*)  !< rows, ascending in each column.
         real(c_double), intent(in) :: values(*)  !< values, as rowind.
      end function chol_set_matrix
      integer(c_int) function chol_analyze(key, lnz, flops, bytes) &
            bind(c, name='impact_cholmod_analyze')
         import :: c_long_long, c_int, c_double
         integer(c_long_long), value :: key  !< the handle.
         real(c_double), intent(out) :: lnz, flops, bytes  !< nnz(L), flops, bytes of the numeric factor.
      end function chol_analyze
      integer(c_int) function chol_factorize(key, minor) bind(c, name='impact_cholmod_factorize')
         import :: c_long_long, c_int
         integer(c_long_long), value :: key  !< the handle.
         integer(c_long_long), intent(out) :: minor  !< 1-based failed column, n+1 if none.
      end function chol_factorize
      integer(c_int) function chol_diagonal(key, n, diag, perm) &
            bind(c, name='impact_cholmod_diagonal')
         import :: c_long_long, c_int, c_double
         integer(c_long_long), value :: key  !< the handle.
         integer(c_long_long), value :: n  !< order.
         real(c_double), intent(out) :: diag(*)  !< L(k,k), k in elimination order.
         integer(c_long_long), intent(out) :: perm(*)  !< equation eliminated k-th (1-based).
      end function chol_diagonal
      integer(c_int) function chol_solve(key, n, b) bind(c, name='impact_cholmod_solve')
         import :: c_long_long, c_int, c_double
         integer(c_long_long), value :: key  !< the handle.
         integer(c_long_long), value :: n  !< order.
         real(c_double), intent(inout) :: b(*)  !< right-hand side in, solution out.
      end function chol_solve
   end interface

contains

   !> Number of factorizations alive in the shim's table (the tests check
   !> that the matrices release theirs).
   integer function cholmod_live_handles()
      cholmod_live_handles = int(chol_live())
   end function cholmod_live_handles

   !> stat and errmsg from a return code of the shim: what it means.
   subroutine chol_check(code, what, stat, errmsg)
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
      case default; text = 'CHOLMOD failed with status ' // int_str(int(chol_status()))
      end select
      stat = 1
      errmsg = 'sparse (CHOLMOD): ' // what // ' failed: ' // text
   end subroutine chol_check

end module cholmod_binding
