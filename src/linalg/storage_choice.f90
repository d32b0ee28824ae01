!> Which storage the global matrices take (&analysis storage) and what the
!> run's matrices will cost in each, before any is built: 'auto' is band
!> below sparse_crossover equations (and for modes: LAPACK's banded
!> eigensolver), sparse (CHOLMOD) from there on. Not from the paper.
!> The measurements behind it: docs/PERFORMANCE.md, "Sparse storage (CHOLMOD)".
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

   !> Memory of the run's matrices in a storage, bytes, from the equations N and the
   !> half-bandwidth kd estimated from the mesh (the deck's check): band, skyline: [M], [K_L]
   !> and K_L + 4/dt^2 M, N (kd + 1) reals each; sparse: entry_bytes for each entry of the
   !> upper triangle (M, K_L, the sum, CHOLMOD's copies), and factor_entry_bytes for each of
   !> the factor's 0.6 N log2(N)^2 entries (a fit to CHOLMOD's analysis of plates; the run
   !> checks the analysis itself, sparse_matrix).
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
