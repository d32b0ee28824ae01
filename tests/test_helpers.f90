!> What the tests share: a run's results read back (src/results/result_reader.f90),
!> a text file's lines, and the random assembled systems of the solver tests
!> (tests/test_solvers.pf, tests/test_sparse.pf). Built and linked with the
!> tests in both routes (tests/tests.mk).
module test_helpers
   use, intrinsic :: iso_fortran_env, only: int64
   use kinds, only: dp, msg_len
   use result_reader, only: summary_t, read_summary, summary_value, summary_string
   use global_matrix, only: global_matrix_t, global_init, global_assemble, global_matvec
   implicit none
   private
   public :: line_len, read_lines, result_lines, summary_number, summary_word
   public :: nfe, grid_freedoms, assemble_system, random_spd, random_vector, dense_of

   !> Length of a line read (read_lines, result_lines).
   integer, parameter :: line_len = 1024
   !> Freedoms of a node, of a 9-node element (the solver tests' grid).
   integer, parameter :: nfree = 5, nfe = 9*nfree
   !> The Park-Miller generator's modulus, 2**31 - 1.
   integer(int64), parameter :: pm_modulus = 2147483647_int64

contains

   !> The lines of a text file (none when it cannot be read).
   subroutine read_lines(path, lines)
      character(len=*), intent(in) :: path
      character(len=line_len), allocatable, intent(out) :: lines(:)
      character(len=line_len), allocatable :: grown(:)
      integer :: u, ios, n
      allocate (lines(64))
      n = 0
      open (newunit=u, file=path, status='old', action='read', iostat=ios)
      if (ios /= 0) lines = lines(:0)
      if (ios /= 0) return
      do while (ios == 0)
         if (n == size(lines)) then          ! doubled: a long history reads in linear time
            allocate (grown(2*n))
            grown(:n) = lines
            call move_alloc(grown, lines)
         end if
         read (u, '(a)', iostat=ios) lines(n + 1)
         if (ios == 0) n = n + 1
      end do
      close (u, iostat=ios)
      lines = lines(:n)
   end subroutine read_lines

   !> The lines of a result file that `keep` accepts: rows ('r': not blank,
   !> no '#' first) or summary items ('s': those but cpu_s, which varies).
   subroutine result_lines(path, keep, lines)
      character(len=*), intent(in) :: path
      character, intent(in) :: keep
      character(len=line_len), allocatable, intent(out) :: lines(:)
      logical, allocatable :: kept(:)
      call read_lines(path, lines)
      kept = lines(:)(1:1) /= '#' .and. len_trim(lines) > 0
      if (keep == 's') kept = kept .and. index(lines, 'cpu_s =') /= 1
      lines = pack(lines, kept)
   end subroutine result_lines

   !> The number of `key = value` in a summary file (huge when absent).
   real(dp) function summary_number(path, key) result(x)
      character(len=*), intent(in) :: path, key
      type(summary_t) :: s
      character(len=msg_len) :: errmsg
      integer :: stat
      call read_summary(path, s, stat, errmsg)
      x = summary_value(s, key, huge(1.0_dp))
   end function summary_number

   !> The text of `key = value` in a summary file ('' when absent).
   function summary_word(path, key) result(text)
      character(len=*), intent(in) :: path, key
      character(len=:), allocatable :: text
      type(summary_t) :: s
      character(len=msg_len) :: errmsg
      integer :: stat
      call read_summary(path, s, stat, errmsg)
      text = summary_string(s, key)
   end function summary_word

   !> Equation table of an nx x ny grid of 9-node elements, 5 freedoms per
   !> node, numbered node by node across the short (y) side; all freedoms
   !> held on the edge x = 0 and, with w_far, w on the edge x = 2 nx.
   subroutine grid_freedoms(nx, ny, elem_eq, neq, w_far)
      integer, intent(in) :: nx, ny                        !< elements along x, y
      integer, allocatable, intent(out) :: elem_eq(:,:)    !< elem_eq(nfe, nx*ny), 0 held
      integer, intent(out) :: neq                          !< number of equations
      logical, intent(in), optional :: w_far               !< w held on x = 2 nx too
      integer, allocatable :: node_eq(:,:)
      integer :: ix, iy, f, node, ex, ey, e, k, npy
      logical :: far
      far = .false.
      if (present(w_far)) far = w_far
      npy = 2*ny + 1
      allocate (node_eq(nfree, (2*nx + 1)*npy))
      neq = 0
      do ix = 0, 2*nx
         do iy = 0, 2*ny
            node = ix*npy + iy + 1
            do f = 1, nfree
               node_eq(f, node) = 0
               if (ix == 0 .or. (far .and. ix == 2*nx .and. f == 3)) cycle
               neq = neq + 1
               node_eq(f, node) = neq
            end do
         end do
      end do
      allocate (elem_eq(nfe, nx*ny))
      e = 0
      do ex = 1, nx
         do ey = 1, ny
            e = e + 1
            k = 0
            do ix = 2*ex - 2, 2*ex
               do iy = 2*ey - 2, 2*ey
                  elem_eq(k*nfree + 1:(k + 1)*nfree, e) = node_eq(:, ix*npy + iy + 1)
                  k = k + 1
               end do
            end do
         end do
      end do
   end subroutine grid_freedoms

   !> Random SPD element matrices assembled into g (through global_matrix)
   !> and into a full dense matrix (directly), from the same seed.
   subroutine assemble_system(storage, elem_eq, neq, seed, g, dense, stat, errmsg)
      character(len=*), intent(in) :: storage              !< 'band', 'skyline' or 'sparse'
      integer, intent(in) :: elem_eq(:,:)                  !< equation table elem_eq(nfe, nelem)
      integer, intent(in) :: neq                           !< number of equations
      integer(int64), intent(in) :: seed                   !< seed of the element matrices
      type(global_matrix_t), intent(out) :: g              !< the assembled global matrix
      real(dp), allocatable, intent(out) :: dense(:,:)     !< the same matrix, dense and full
      integer, intent(out) :: stat                         !< 0 on success
      character(len=*), intent(inout) :: errmsg            !< reason for a failure
      real(dp) :: ke(nfe, nfe)
      integer(int64) :: state
      integer :: e, p, q, ip, iq
      call global_init(g, storage, neq, elem_eq, stat, errmsg)
      if (stat /= 0) return
      allocate (dense(neq, neq))
      dense = 0.0_dp
      state = seed
      do e = 1, size(elem_eq, 2)
         call random_spd(state, ke)
         call global_assemble(g, ke, elem_eq(:, e), stat, errmsg)
         if (stat /= 0) return
         do q = 1, nfe
            iq = elem_eq(q, e)
            do p = 1, nfe
               ip = elem_eq(p, e)
               if (ip > 0 .and. iq > 0) dense(ip, iq) = dense(ip, iq) + ke(p, q)
            end do
         end do
      end do
   end subroutine assemble_system

   !> Random symmetric positive definite matrix R^T R / n + I / 10, R with
   !> entries uniform in [-1, 1).
   subroutine random_spd(state, ke)
      integer(int64), intent(inout) :: state               !< generator state, advanced
      real(dp), intent(out) :: ke(:,:)                     !< the matrix, square
      real(dp) :: r(size(ke, 1), size(ke, 1))
      integer :: k
      do k = 1, size(r, 2)
         call random_vector(state, r(:, k))
      end do
      ke = matmul(transpose(r), r)/real(size(ke, 1), dp)
      ke = 0.5_dp*(ke + transpose(ke))
      do k = 1, size(ke, 1)
         ke(k, k) = ke(k, k) + 0.1_dp
      end do
   end subroutine random_spd

   !> Uniform numbers in [-1, 1) from the Park-Miller minimal standard
   !> generator, state_{k+1} = 16807 state_k mod (2**31 - 1).
   subroutine random_vector(state, v)
      integer(int64), intent(inout) :: state               !< generator state in 1 .. 2**31-2, advanced
      real(dp), intent(out) :: v(:)                        !< the numbers
      integer :: k
      do k = 1, size(v)
         state = mod(16807_int64*state, pm_modulus)
         v(k) = 2.0_dp*real(state, dp)/real(pm_modulus, dp) - 1.0_dp
      end do
   end subroutine random_vector

   !> The unfactored global matrix g as a dense array, column j = A e_j (global_matvec).
   function dense_of(g) result(d)
      type(global_matrix_t), intent(in) :: g               !< the matrix, not factored
      real(dp) :: d(g%neq, g%neq)
      real(dp) :: e(g%neq)
      integer :: j
      do j = 1, g%neq
         e = 0.0_dp
         e(j) = 1.0_dp
         call global_matvec(g, e, d(:, j))
      end do
   end function dense_of

end module test_helpers
