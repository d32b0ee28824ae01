!> Which storage the global matrices take (&analysis storage), and what
!> the run's matrices will cost in memory in each, before any is built.
!> 'auto' (the default) picks band storage below sparse_crossover = 3000
!> equations and sparse storage (CHOLMOD) from there on; the modal analysis
!> needs band storage (LAPACK's banded eigensolver), so 'auto' is band
!> there. The memory model: the comment above matrices_memory.
!> Not from the paper. The measurements behind the crossover and the
!> memory model: docs/PERFORMANCE.md, "Sparse storage (CHOLMOD)".
module storage_choice
   use kinds, only: dp
   implicit none
   private
   public :: sparse_crossover, storage_name_len, resolve_storage, matrices_memory

   !> Equations from which 'auto' chooses sparse storage (docs/PERFORMANCE.md).
   integer, parameter :: sparse_crossover = 3000
   !> Length of a storage name ('band', 'skyline', 'sparse').
   integer, parameter :: storage_name_len = 8
   !> Stored entries of the upper triangle per equation, 9-node plate mesh.
   real(dp), parameter :: entries_per_equation = 40.0_dp
   !> Bytes a stored entry costs in all the copies of a sparse run (above matrices_memory).
   real(dp), parameter :: entry_bytes = 80.0_dp
   !> Entries of the factor per N log2(N)^2 (above matrices_memory).
   real(dp), parameter :: factor_fill = 0.6_dp
   !> Bytes a factor entry costs (its real and its share of the indices).
   real(dp), parameter :: factor_entry_bytes = 10.0_dp

contains

   !> The storage the run takes: the one requested, with 'auto' resolved by
   !> the number of equations (sparse_crossover); band when only band will do.
   pure function resolve_storage(requested, neq, band_only) result(storage)
      character(len=*), intent(in) :: requested  !< &analysis storage: 'auto', 'band', 'skyline' or 'sparse'.
      integer, intent(in) :: neq  !< number of equations.
      logical, intent(in) :: band_only  !< the analysis needs band storage (kind = 'modes').
      character(len=storage_name_len) :: storage

      storage = requested
      if (requested /= 'auto') return
      if (band_only .or. neq < sparse_crossover) then
         storage = 'band'
      else
         storage = 'sparse'
      end if
   end function resolve_storage

   !> Memory of the run's matrices in a storage, bytes (the pre-flight check of the deck, from
   !> the equations and the half-bandwidth estimated from the mesh):
   !>  - band, skyline: three band matrices of N (kd + 1) reals, [M], [K_L]
   !>    and the factored K_L + 4/dt^2 M (skyline's profile is at most the
   !>    band);
   !>  - sparse: entry_bytes = 80 bytes for each of the 40 entries an equation
   !>    has on a 9-node mesh (the upper triangle; [M] and [K_L] in compressed
   !>    columns, 12 bytes an entry, kept; K_L + 4/dt^2 M likewise until it is
   !>    handed over; CHOLMOD's copy of it and its permuted copy during the
   !>    factorization, 16 bytes an entry each), and the factor: 10 bytes
   !>    (its reals and its row indices) for each of its 0.6 N log2(N)^2
   !>    entries, the fit to CHOLMOD's analysis of plates from 1 000 to
   !>    447 000 equations (within 6 %; nested dissection on a plate). With
   !>    the element work this was within 15 % of the peak memory measured
   !>    from 68 000 to 447 000 equations (docs/PERFORMANCE.md). The run
   !>    itself checks the exact size of the factor, from CHOLMOD's analysis,
   !>    before the numeric factorization (src/linalg/sparse_matrix.f90).
   pure function matrices_memory(storage, neq, kd) result(bytes)
      character(len=*), intent(in) :: storage  !< 'band', 'skyline' or 'sparse' (resolved).
      real(dp), intent(in) :: neq  !< number of equations.
      real(dp), intent(in) :: kd  !< half-bandwidth.
      real(dp) :: bytes
      real(dp) :: log2n

      if (storage == 'sparse') then
         log2n = log(max(neq, 2.0_dp)) / log(2.0_dp)
         bytes = entry_bytes * entries_per_equation * neq + factor_entry_bytes * factor_fill * neq * log2n**2
      else
         bytes = 3.0_dp * neq * (kd + 1.0_dp) * 8.0_dp
      end if
   end function matrices_memory

end module storage_choice
