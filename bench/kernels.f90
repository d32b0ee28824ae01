!> bench_kernels: the cost of the pieces of a time step, each timed alone on
!> the model of a deck (make bench; not a test).
!>
!> Usage:  build/bench/bench_kernels deck.nml
!>
!> Builds the model of the deck and factors K_L + 4/dt^2 M (as ./impact
!> does), then times, each as the fastest of `blocks` blocks of repeated
!> calls (CPU time, so that other jobs on the machine inflate it least):
!>   solve        one plate solve, global_solve (band: LAPACK dpbtrs)
!>   mass         M x element by element, mass_times: once per step for M{b},
!>                once per output step for the kinetic energy
!>   matvec       M x with the assembled matrix, global_matvec (band: BLAS
!>                dsbmv), what mass_times replaced
!>   knl          K_N(D) D of eq. (19), nonlinear_force, once per iteration
!>   energy       the plate strain energy, once per output step
!>   gemm         BLAS dgemm on three n_gemm x n_gemm matrices: the flop rate
!>                the linked BLAS reaches when arithmetic, not memory, limits it
!>   stream       one pass over the stored factor (sum of its entries): the
!>                rate at which the solve can read its 8 (kd+1) N bytes
!>   peak         independent multiply-adds on numbers held in registers: the
!>                machine's arithmetic rate (this file is compiled with -O3
!>                -march=native, so the loop uses the widest vector FMA)
!> and prints `key = value` lines: sizes, seconds per call, and the solve's
!> rate against its flop count 4 N kd (two triangular sweeps of the band,
!> each 2 N kd flops; for skyline storage 4 times the stored off-diagonal
!> entries) and against the time of reading the factor twice.
!> The displacement state of knl and energy is the plate's static-like
!> response to a contact force scaled to a 1 mm deflection at the impact
!> point (the size of the paper's plate deflections), so that the von
!> Karman terms are of their real size; the timings do not depend on it.
program bench_kernels
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit, int64
   use kinds, only: dp, msg_len
   use input_deck, only: deck_t, read_deck_file
   use newmark, only: newmark_t, newmark_init
   use global_matrix, only: global_solve, global_matvec, global_bandwidth, global_stored_entries
   use plate_model, only: model_t, build_model, nonlinear_force, mass_times, plate_strain_energy
   use plate_solver, only: solver_t, solver_init
   implicit none

   !> Fastest of this many timed blocks is reported (many short blocks: the
   !> fastest is the one least disturbed by other jobs on the machine).
   integer, parameter :: blocks = 15
   !> Each block repeats its call until it has run this long (s of CPU time).
   real(dp), parameter :: block_seconds = 0.03_dp
   !> Order of the dgemm matrices (3 x 8 n^2 bytes = 1 MB: in cache).
   integer, parameter :: n_gemm = 200
   !> Deflection at the impact point of the state used by knl and energy (m).
   real(dp), parameter :: w_state = 1.0e-3_dp
   !> The kernels timed.
   integer, parameter :: k_solve = 1, k_matvec = 2, k_knl = 3, k_energy = 4, k_gemm = 5, k_stream = 6, k_mass = 7, k_peak = 8
   !> Independent multiply-add chains of the peak loop (8 vectors of 8 doubles:
   !> enough to cover the FMA latency of two pipelines) and its trip count.
   integer, parameter :: n_chain = 64, n_fma_loop = 100000

   interface
      subroutine dgemm(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc)
         import :: dp
         character(len=1), intent(in) :: transa, transb
         integer, intent(in) :: m, n, k, lda, ldb, ldc
         real(dp), intent(in) :: alpha, beta
         real(dp), intent(in) :: a(lda, *), b(ldb, *)
         real(dp), intent(inout) :: c(ldc, *)
      end subroutine dgemm
   end interface

   type(deck_t) :: deck
   type(model_t) :: model
   type(solver_t) :: solver
   type(newmark_t) :: nm
   real(dp), allocatable :: x(:), y(:), d(:), ga(:,:), gb(:,:), gc(:,:)
   real(dp) :: t_solve, t_mass, t_matvec, t_knl, t_energy, t_gemm, t_stream, t_peak, sink
   real(dp) :: flops_solve, bytes_factor
   integer :: stat, n, kd
   character(len=msg_len) :: errmsg, path

   errmsg = ''
   if (command_argument_count() /= 1) then
      write (error_unit, '(a)') 'usage: bench_kernels deck.nml'
      error stop 1
   end if
   call get_command_argument(1, path)
   call read_deck_file(trim(path), deck, stat, errmsg)
   if (stat /= 0) call fail('input: '//errmsg)
   call build_model(deck, model, stat, errmsg)
   if (stat /= 0) call fail(errmsg)
   nm = newmark_init(deck%dt)
   call solver_init(model, nm, solver, stat, errmsg)
   if (stat /= 0) call fail(errmsg)

   n = model%msh%neq
   kd = global_bandwidth(solver%keff)
   allocate (x(n), y(n), d(n))
   call random_number(x)
   ! a deflected state: the response to a force at the impact point, scaled to w_state there
   d = 0.0_dp
   d(model%eq_impact) = 1.0_dp
   call global_solve(solver%keff, d, stat, errmsg)
   if (stat /= 0) call fail(errmsg)
   d = d*(w_state/d(model%eq_impact))
   sink = 0.0_dp

   t_solve = fastest(k_solve)
   t_mass = fastest(k_mass)
   t_matvec = fastest(k_matvec)
   t_knl = fastest(k_knl)
   t_energy = fastest(k_energy)
   allocate (ga(n_gemm, n_gemm), gb(n_gemm, n_gemm), gc(n_gemm, n_gemm))
   call random_number(ga)
   call random_number(gb)
   gc = 0.0_dp
   t_gemm = fastest(k_gemm)
   t_stream = fastest(k_stream)
   t_peak = fastest(k_peak)

   ! two triangular sweeps, each one multiply-add (2 flops) per stored
   ! off-diagonal entry: 4 N kd for band storage (the diagonals are N divisions)
   flops_solve = 4.0_dp*real(global_stored_entries(solver%keff) - n, dp)
   bytes_factor = 8.0_dp*real(global_stored_entries(solver%keff), dp)
   write (output_unit, '(a,a)') 'deck = ', trim(path)
   write (output_unit, '(a,a)') 'storage = ', trim(solver%keff%storage)
   write (output_unit, '(a,i0)') 'elements = ', model%msh%nelem
   write (output_unit, '(a,i0)') 'equations = ', n
   write (output_unit, '(a,i0)') 'half_bandwidth = ', kd
   write (output_unit, '(a,i0)') 'stored_entries = ', global_stored_entries(solver%keff)
   write (output_unit, '(a,es12.5)') 'solve_s = ', t_solve
   write (output_unit, '(a,es12.5)') 'mass_s = ', t_mass
   write (output_unit, '(a,es12.5)') 'matvec_s = ', t_matvec
   write (output_unit, '(a,es12.5)') 'knl_s = ', t_knl
   write (output_unit, '(a,es12.5)') 'energy_s = ', t_energy
   write (output_unit, '(a,es12.5)') 'solve_flops = ', flops_solve
   write (output_unit, '(a,es12.5)') 'solve_gflop_s = ', flops_solve/t_solve*1.0e-9_dp
   write (output_unit, '(a,es12.5)') 'gemm_gflop_s = ', 2.0_dp*real(n_gemm, dp)**3/t_gemm*1.0e-9_dp
   write (output_unit, '(a,es12.5)') 'peak_gflop_s = ', 2.0_dp*real(n_chain, dp)*real(n_fma_loop, dp)/t_peak*1.0e-9_dp
   write (output_unit, '(a,es12.5)') 'factor_bytes = ', bytes_factor
   write (output_unit, '(a,es12.5)') 'stream_gbyte_s = ', bytes_factor/t_stream*1.0e-9_dp
   ! the solve's bounds: its flops at the peak rate, its two reads of the factor at the stream rate
   write (output_unit, '(a,es12.5)') 'solve_flop_bound_s = ', flops_solve/(2.0_dp*real(n_chain, dp)*real(n_fma_loop, dp)/t_peak)
   write (output_unit, '(a,es12.5)') 'solve_read_bound_s = ', 2.0_dp*t_stream
   write (output_unit, '(a,es12.5)') 'checksum = ', sink

contains

   subroutine fail(message)
      character(len=*), intent(in) :: message
      write (error_unit, '(a)') 'bench_kernels: error: '//trim(message)
      error stop 1
   end subroutine fail

   !> CPU seconds per call of kernel k: the fastest of `blocks` blocks,
   !> each repeating the call until block_seconds have passed.
   function fastest(k) result(t_best)
      integer, intent(in) :: k   !< kernel (k_solve, ...)
      real(dp) :: t_best
      real(dp) :: t0, t1
      integer(int64) :: calls
      integer :: b
      t_best = huge(1.0_dp)
      timed_blocks: do b = 1, blocks
         calls = 0
         call cpu_time(t0)
         t1 = t0
         do while (t1 - t0 < block_seconds)
            call run_kernel(k)
            calls = calls + 1
            call cpu_time(t1)
         end do
         t_best = min(t_best, (t1 - t0)/real(calls, dp))
      end do timed_blocks
   end function fastest

   !> One call of kernel k; its result goes into sink so that it is kept.
   subroutine run_kernel(k)
      integer, intent(in) :: k   !< kernel (k_solve, ...)
      select case (k)
      case (k_solve)
         y = x
         call global_solve(solver%keff, y, stat, errmsg)
         if (stat /= 0) call fail(errmsg)
         sink = sink + y(1)
      case (k_matvec)
         call global_matvec(model%mass, x, y, stat, errmsg)
         if (stat /= 0) call fail(errmsg)
         sink = sink + y(1)
      case (k_mass)
         call mass_times(model, x, y)
         sink = sink + y(1)
      case (k_knl)
         call nonlinear_force(model, d, y)
         sink = sink + y(1)
      case (k_energy)
         sink = sink + plate_strain_energy(model, d)
      case (k_gemm)
         call dgemm('N', 'N', n_gemm, n_gemm, n_gemm, 1.0_dp, ga, n_gemm, gb, n_gemm, 0.0_dp, gc, n_gemm)
         sink = sink + gc(1, 1)
      case (k_peak)
         sink = sink + fma_chains()
      case (k_stream)
         ! the storage the model took ('auto' resolved); CHOLMOD's factor
         ! (sparse) is not Fortran's to read
         if (solver%keff%storage == 'band') then
            sink = sink + read_all(solver%keff%band%ab, size(solver%keff%band%ab))
         else if (solver%keff%storage == 'skyline') then
            sink = sink + read_all(solver%keff%sky%a, size(solver%keff%sky%a))
         end if
      end select
   end subroutine run_kernel

   !> n_chain independent chains of n_fma_loop multiply-adds each (2 flops);
   !> the factors keep the numbers bounded (x -> 0.999 x + 0.001 tends to 1).
   function fma_chains() result(total)
      real(dp) :: total
      real(dp) :: x(n_chain)
      real(dp), parameter :: c = 0.999_dp, e = 0.001_dp
      integer :: i, it
      x = [(real(i, dp)/n_chain, i = 1, n_chain)]
      do it = 1, n_fma_loop
         x = c*x + e
      end do
      total = sum(x)
   end function fma_chains

   !> Sum of the m numbers of a, read once in order with eight independent
   !> partial sums (no dependence chain: the loop runs at the rate memory
   !> delivers the numbers).
   function read_all(a, m) result(total)
      integer, intent(in) :: m        !< number of entries
      real(dp), intent(in) :: a(m)    !< the stored matrix, by sequence association
      real(dp) :: total
      integer, parameter :: stride = 8
      real(dp) :: part(stride)
      integer :: i
      part = 0.0_dp
      do i = 1, m - stride + 1, stride
         part = part + a(i:i+stride-1)
      end do
      total = sum(part) + sum(a(i:m))
   end function read_all

end program bench_kernels
