!> The global matrices [M], [K_L] and K_L + 4/dt^2 M of eq. (19) in a
!> storage chosen at run time: band, skyline or sparse (CHOLMOD), each
!> documented in its module; 'auto' by storage_choice. The structure comes
!> from the element freedom table elem_eq (0 = constrained). Use: global_init,
!> global_assemble per element, global_axpy_matrix, global_factor once,
!> global_solve every step. Errors: stat and errmsg; without stat a failed
!> assembly is reported by the next factor or solve. More: docs/ALGORITHM.md.
module global_matrix
   use kinds, only: dp, msg_len
   use number_text, only: int_str
   use band_matrix, only: band_matrix_t, band_init, band_in_band, band_add, band_matvec, &
                          band_factor, band_solve, band_axpy
   use skyline_matrix, only: skyline_matrix_t, skyline_init, skyline_in_profile, skyline_add, skyline_axpy, &
                             skyline_half_bandwidth, skyline_matvec, skyline_factor, skyline_solve
   use sparse_matrix, only: sparse_matrix_t, sparse_init, sparse_zero, sparse_in_pattern, sparse_add, &
                            sparse_matvec, sparse_axpy, sparse_factor, sparse_solve, &
                            sparse_half_bandwidth, sparse_entries, sparse_release, sparse_copy_factor
   use storage_choice, only: storage_len => storage_name_len, resolve_storage
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   implicit none
   private
   public :: global_matrix_t
   public :: global_init, global_zero, global_assemble, global_axpy_matrix, &
             global_copy, global_matvec, global_factor, global_solve, &
             global_bandwidth, global_stored_entries, global_release

   !> A global matrix in the storage named by `storage`; only that one of
   !> `band`, `sky` and `sparse` is allocated.
   type :: global_matrix_t
      character(len=storage_len) :: storage = ''  !< 'band', 'skyline' or 'sparse' ('' before global_init).
      integer :: neq = 0  !< number of equations.
      type(band_matrix_t) :: band  !< the matrix when storage = 'band'.
      type(skyline_matrix_t) :: sky  !< the matrix when storage = 'skyline'.
      type(sparse_matrix_t) :: sparse  !< the matrix when storage = 'sparse'.
      !> First error of an assembly or addition called without stat
      !> ('' = none); reported by global_factor and global_solve.
      character(len=msg_len) :: deferred_error = ''
   end type global_matrix_t

contains

   !> Find the structure from the element freedom table and allocate a
   !> zero matrix in the chosen storage (what g held before is released).
   subroutine global_init(g, storage, neq, elem_eq, stat, errmsg)
      type(global_matrix_t), intent(inout) :: g  !< the matrix, released and (re)defined here.
      character(len=*), intent(in) :: storage  !< 'band', 'skyline', 'sparse' or 'auto' (by neq; case and blanks ignored).
      integer, intent(in) :: neq  !< number of equations, >= 1.
      integer, intent(in) :: elem_eq(:,:)  !< elem_eq(k, e): equation of freedom k of element e, 0 = constrained.
      integer, intent(out) :: stat  !< 0 on success, 1 on failure.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      character(len=storage_len) :: name
      integer, allocatable :: first_row(:)
      integer :: e, k, eq, lo, kd, bad(2)
      call global_release(g)
      stat = 1
      bad = findloc(elem_eq < 0 .or. elem_eq > neq, .true.)       ! 0 (constrained) or 1..neq
      if (neq < 1) then
         errmsg = 'global_init: number of equations must be >= 1, got ' // int_str(neq)
         return
      else if (bad(1) > 0) then
         errmsg = 'global_init: element ' // int_str(bad(2)) // ' freedom ' // int_str(bad(1)) // ' has equation ' &
            // int_str(elem_eq(bad(1), bad(2))) // ' outside 0..' // int_str(neq)
         return
      end if

      name = resolve_storage(lower(trim(adjustl(storage))), neq, .false.)
      select case (trim(name))
      case ('band')
         ! kd = max over elements of (largest - smallest equation).
         kd = 0
         do e = 1, size(elem_eq, 2)
            if (any(elem_eq(:, e) > 0)) kd = max(kd, maxval(elem_eq(:, e)) - minval(elem_eq(:, e), mask=elem_eq(:, e) > 0))
         end do
         call band_init(g%band, neq, kd, stat, errmsg)
      case ('skyline')
         ! m_j = min over elements holding j of their smallest equation.
         first_row = [(eq, eq = 1, neq)]
         do e = 1, size(elem_eq, 2)
            if (all(elem_eq(:, e) == 0)) cycle
            lo = minval(elem_eq(:, e), mask=elem_eq(:, e) > 0)
            do k = 1, size(elem_eq, 1)
               eq = elem_eq(k, e)
               if (eq > 0) first_row(eq) = min(first_row(eq), lo)
            end do
         end do
         call skyline_init(g%sky, neq, first_row, stat, errmsg)
      case ('sparse')
         call sparse_init(g%sparse, neq, elem_eq, stat, errmsg)
      case default                                  ! (stat = 1)
         errmsg = "global_init: unknown storage '" // trim(storage) // &
                   "' (expected 'band', 'skyline', 'sparse' or 'auto')"
      end select
      if (stat /= 0) return
      g%storage = trim(name)
      g%neq = neq
   end subroutine global_init

   !> Set every entry to zero, forget any factorisation and any deferred
   !> error; the structure is kept.
   subroutine global_zero(g)
      type(global_matrix_t), intent(inout) :: g  !< the matrix.
      if (allocated(g%band%ab)) g%band%ab = 0.0_dp
      if (allocated(g%sky%a)) g%sky%a = 0.0_dp
      g%band%factored = .false.
      g%sky%factored = .false.
      call sparse_zero(g%sparse)                    ! (nothing unless sparse)
      g%deferred_error = ''
   end subroutine global_zero

   !> Add a symmetric element matrix, A(eqs(p), eqs(q)) += ke(p,q) for eqs(p) <=
   !> eqs(q) > 0. Fails, adding nothing, when g is not initialised or is
   !> factored, the sizes differ, or an entry is outside the structure.
   subroutine global_assemble(g, ke, eqs, stat, errmsg)
      type(global_matrix_t), intent(inout) :: g  !< the global matrix, added into.
      real(dp), intent(in) :: ke(:,:)  !< symmetric element matrix ke(nfe, nfe).
      integer, intent(in) :: eqs(:)  !< global equations of the element freedoms, eqs(nfe), 0 = skip.
      integer, intent(out), optional :: stat  !< 0 on success, 1 on failure (optional; see module header).
      character(len=*), intent(inout), optional :: errmsg  !< reason for the failure (optional, set only on failure).
      character(len=msg_len) :: msg
      integer :: p, q, ip, iq
      if (present(stat)) stat = 0
      msg = ''
      if (len_trim(g%storage) == 0) then
         msg = 'global_assemble: the matrix was never initialised'
      else if (is_factored(g)) then
         msg = 'global_assemble: the matrix is factored'
      else if (size(ke, 1) /= size(eqs) .or. size(ke, 2) /= size(eqs)) then
         write (msg, '(a,i0,a,i0,a,i0)') 'global_assemble: ke is ', size(ke, 1), &
            ' x ', size(ke, 2), ' but size(eqs) = ', size(eqs)
      else if (any(eqs < 0 .or. eqs > g%neq)) then
         write (msg, '(a,i0)') 'global_assemble: an equation is outside 0..', g%neq
      else
         check: do q = 1, size(eqs)
            do p = 1, size(eqs)
               if (eqs(p) == 0 .or. eqs(q) == 0 .or. eqs(p) > eqs(q)) cycle
               if (.not. in_structure(g, eqs(p), eqs(q))) then
                  write (msg, '(a,i0,a,i0,a)') 'global_assemble: entry (', eqs(p), ',', &
                     eqs(q), ') is outside the structure found by global_init'
                  exit check
               end if
            end do
         end do check
      end if
      if (len_trim(msg) > 0) then
         call report(g, msg, stat, errmsg)
         return
      end if

      columns: do q = 1, size(eqs)
         iq = eqs(q)
         do p = 1, size(eqs)
            ip = eqs(p)
            if (ip == 0 .or. iq == 0 .or. ip > iq) cycle
            select case (g%storage)
            case ('band'); call band_add(g%band, ip, iq, ke(p, q))
            case ('skyline'); call skyline_add(g%sky, ip, iq, ke(p, q))
            case default; call sparse_add(g%sparse, ip, iq, ke(p, q))
            end select
         end do
      end do columns
   end subroutine global_assemble

   !> g = g + alpha*other, for two unfactored matrices built by global_init
   !> with the same storage, neq and elem_eq (e.g. K + 4/dt**2 M).
   subroutine global_axpy_matrix(g, alpha, other, stat, errmsg)
      type(global_matrix_t), intent(inout) :: g  !< the matrix added into.
      real(dp), intent(in) :: alpha  !< scalar multiplying other.
      type(global_matrix_t), intent(in) :: other  !< the matrix added; same structure as g.
      integer, intent(out), optional :: stat  !< 0 on success, 1 on failure (optional; see module header).
      character(len=*), intent(inout), optional :: errmsg  !< reason for the failure (optional, set only on failure).
      character(len=msg_len) :: msg
      integer :: ierr
      if (present(stat)) stat = 0
      msg = ''
      if (g%storage /= other%storage .or. len_trim(g%storage) == 0) then
         msg = "global_axpy_matrix: storages differ or are not initialised ('" // &
               trim(g%storage) // "', '" // trim(other%storage) // "')"
      else if (g%band%factored .or. g%sky%factored .or. other%band%factored .or. other%sky%factored) then
         msg = trim(g%storage) // '_axpy: a factored matrix cannot be added to or from'
      else
         select case (trim(g%storage))
         case ('band'); call band_axpy(g%band, alpha, other%band, ierr, msg)
         case ('skyline'); call skyline_axpy(g%sky, alpha, other%sky, ierr, msg)
         case ('sparse'); call sparse_axpy(g%sparse, alpha, other%sparse, ierr, msg)
         end select
      end if
      if (len_trim(msg) > 0) then
         call report(g, 'global_axpy_matrix: ' // trim(msg), stat, errmsg)
         return
      end if
      ! A matrix added from a failed assembly carries its error along.
      if (len_trim(g%deferred_error) == 0) g%deferred_error = other%deferred_error
   end subroutine global_axpy_matrix

   !> dst = src (storage, structure, values, factorisation; a sparse factor
   !> is copied, not shared; what dst held before is released). A failed
   !> copy of the factor (no memory) is recorded in dst (deferred_error).
   subroutine global_copy(dst, src)
      type(global_matrix_t), intent(inout) :: dst  !< the copy.
      type(global_matrix_t), intent(in) :: src  !< the matrix copied.
      character(len=msg_len) :: msg
      integer :: stat
      call global_release(dst)
      dst = src
      if (src%storage /= 'sparse') return
      msg = ''
      call sparse_copy_factor(src%sparse, dst%sparse, stat, msg)
      if (stat /= 0) call report(dst, 'global_copy: ' // trim(msg))
   end subroutine global_copy

   !> Release everything g holds (CHOLMOD's factor included); g is then as before global_init.
   subroutine global_release(g)
      type(global_matrix_t), intent(inout) :: g  !< the matrix.
      if (g%storage == 'sparse') call sparse_release(g%sparse)
      g = global_matrix_t()
   end subroutine global_release

   !> y = A x with the unfactored matrix; y is NaN when g is not initialised,
   !> factored or carries a deferred error, or the sizes differ.
   subroutine global_matvec(g, x, y, stat, errmsg)
      type(global_matrix_t), intent(in) :: g     !< the matrix, not factored
      real(dp), intent(in) :: x(:)               !< a vector of length neq
      real(dp), intent(out) :: y(:)              !< A x
      integer, intent(out), optional :: stat     !< 0 on success, 1 on failure
      character(len=*), intent(inout), optional :: errmsg  !< reason for the failure (set only on failure).
      character(len=msg_len) :: msg
      integer :: ierr
      if (present(stat)) stat = 0
      msg = ''
      if (.not. usable(g, 'global_matvec', ierr, msg)) then
         continue
      else if (is_factored(g)) then
         msg = 'global_matvec: the matrix holds its factors, not A'
      else if (size(x) /= g%neq .or. size(y) /= g%neq) then
         msg = 'global_matvec: size(x) = ' // int_str(size(x)) // ', size(y) = ' // int_str(size(y)) &
            // ' but neq = ' // int_str(g%neq)
      else if (g%storage == 'band') then
         call band_matvec(g%band, x, y)
      else if (g%storage == 'skyline') then
         call skyline_matvec(g%sky, x, y)
      else
         call sparse_matvec(g%sparse, x, y)
      end if
      if (len_trim(msg) > 0) then
         y = ieee_value(1.0_dp, ieee_quiet_nan)
         if (present(stat)) stat = 1
         if (present(errmsg)) errmsg = msg
      end if
   end subroutine global_matvec

   !> Factor in place (band: Cholesky, skyline: L D L^T, sparse: CHOLMOD). A
   !> failed pivot gives stat = 1 and bad_eq, whose node the caller names.
   subroutine global_factor(g, stat, errmsg, bad_eq)
      type(global_matrix_t), intent(inout) :: g  !< the matrix, overwritten by its factors.
      integer, intent(out) :: stat  !< 0 on success, 1 on failure.
      character(len=*), intent(inout) :: errmsg  !< reason for the failure (set only on failure).
      integer, intent(out) :: bad_eq  !< equation whose pivot failed, 0 if none did.
      bad_eq = 0
      if (.not. usable(g, 'global_factor', stat, errmsg)) return
      if (g%band%factored .or. g%sky%factored) then     ! (sparse_factor says it itself)
         stat = 1
         errmsg = trim(g%storage) // '_factor: the matrix is already factored'
         return
      end if
      select case (g%storage)
      case ('band'); call band_factor(g%band, stat, errmsg, bad_eq)
      case ('skyline'); call skyline_factor(g%sky, stat, errmsg, bad_eq)
      case default; call sparse_factor(g%sparse, stat, errmsg, bad_eq)
      end select
   end subroutine global_factor

   !> Solve A x = b with the factored matrix; b is overwritten by x.
   subroutine global_solve(g, b, stat, errmsg)
      type(global_matrix_t), intent(in) :: g        !< the factored matrix
      real(dp), intent(inout) :: b(:)               !< right-hand side on entry, solution on return (neq)
      integer, intent(out) :: stat                  !< 0 on success, 1 on failure
      character(len=*), intent(inout) :: errmsg     !< reason for the failure (set only on failure)
      if (.not. usable(g, 'global_solve', stat, errmsg)) return
      if (.not. is_factored(g)) then
         stat = 1
         errmsg = trim(g%storage) // '_solve: the matrix is not factored (call ' // trim(g%storage) // '_factor first)'
      else if (size(b) /= g%neq) then
         stat = 1
         errmsg = trim(g%storage) // '_solve: right-hand side has length ' // int_str(size(b)) // ' but n = ' &
            // int_str(g%neq)
      else if (g%storage == 'band') then
         call band_solve(g%band, b, stat, errmsg)
      else if (g%storage == 'skyline') then
         call skyline_solve(g%sky, b)
      else
         call sparse_solve(g%sparse, b, stat, errmsg)
      end if
   end subroutine global_solve

   !> True when g can be used: initialised and without a deferred error
   !> (module header); otherwise stat = 1 and errmsg says why.
   logical function usable(g, caller, stat, errmsg)
      type(global_matrix_t), intent(in) :: g        !< the matrix
      character(len=*), intent(in) :: caller        !< the routine asking, for the message
      integer, intent(out) :: stat                  !< 0 when usable, else 1
      character(len=*), intent(inout) :: errmsg     !< the reason, when not
      stat = 0
      if (len_trim(g%deferred_error) > 0) then
         stat = 1
         errmsg = g%deferred_error
      else if (g%storage /= 'band' .and. g%storage /= 'skyline' .and. g%storage /= 'sparse') then
         stat = 1
         errmsg = caller // ': the matrix was never initialised'
      end if
      usable = stat == 0
   end function usable

   !> Half-bandwidth: the largest j - i of a stored entry (band: kd); 0 before global_init.
   pure integer function global_bandwidth(g)
      type(global_matrix_t), intent(in) :: g  !< the matrix.
      select case (trim(g%storage))
      case ('band'); global_bandwidth = g%band%kd
      case ('skyline'); global_bandwidth = skyline_half_bandwidth(g%sky)
      case ('sparse'); global_bandwidth = sparse_half_bandwidth(g%sparse)
      case default; global_bandwidth = 0
      end select
   end function global_bandwidth

   !> Number of stored reals of A (sparse: the pattern's; the factor's are
   !> g%sparse%factor_entries).
   pure integer function global_stored_entries(g)
      type(global_matrix_t), intent(in) :: g  !< the matrix.
      select case (trim(g%storage))
      case ('band'); global_stored_entries = size(g%band%ab)
      case ('skyline'); global_stored_entries = size(g%sky%a)
      case ('sparse'); global_stored_entries = int(sparse_entries(g%sparse))
      case default; global_stored_entries = 0
      end select
   end function global_stored_entries

   ! ---- private helpers ----------------------------------------------------

   !> True when the stored structure holds A(i,j).
   pure logical function in_structure(g, i, j)
      type(global_matrix_t), intent(in) :: g     !< the matrix
      integer, intent(in) :: i, j                !< row and column indices
      select case (trim(g%storage))
      case ('band'); in_structure = band_in_band(g%band, i, j)
      case ('skyline'); in_structure = skyline_in_profile(g%sky, i, j)
      case ('sparse'); in_structure = sparse_in_pattern(g%sparse, i, j)
      case default; in_structure = .false.
      end select
   end function in_structure

   !> True when the selected storage holds a factorisation.
   pure logical function is_factored(g)
      type(global_matrix_t), intent(in) :: g  !< the matrix.
      is_factored = g%band%factored .or. g%sky%factored .or. g%sparse%factored
   end function is_factored

   !> Hand a failure to the caller's stat/errmsg, or record it in g.
   subroutine report(g, msg, stat, errmsg)
      type(global_matrix_t), intent(inout) :: g  !< the matrix, which records the failure when stat is absent.
      character(len=*), intent(in) :: msg  !< what failed.
      integer, intent(out), optional :: stat  !< the caller's stat, set to 1 when present.
      character(len=*), intent(inout), optional :: errmsg  !< the caller's errmsg, set to msg when present.
      if (present(stat)) then
         stat = 1
         if (present(errmsg)) errmsg = msg
      else if (len_trim(g%deferred_error) == 0) then
         g%deferred_error = msg
      end if
   end subroutine report

   !> Lower-case copy of an ASCII string.
   pure function lower(s) result(t)
      character(len=*), intent(in) :: s  !< the string.
      character(len=len(s)) :: t
      integer :: k
      t = s
      do k = 1, len(s)
         if (s(k:k) >= 'A' .and. s(k:k) <= 'Z') t(k:k) = achar(iachar(s(k:k)) + 32)   ! ASCII
      end do
   end function lower

end module global_matrix
