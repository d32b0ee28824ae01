!> Working precision and the few named constants every module shares.
!>
!> One kinds module for the whole code (fortran-lang stdlib style): `dp` is
!> IEEE double precision from `iso_fortran_env`; every real literal carries
!> `_dp`.
module kinds
   use, intrinsic :: iso_fortran_env, only: real64
   implicit none
   private
   public :: dp, pi, msg_len

   !> Double precision real kind.
   integer, parameter :: dp = real64
   !> pi to double precision.
   real(dp), parameter :: pi = 3.14159265358979323846264338327950288_dp
   !> Length of the error messages that travel up with a status value.
   integer, parameter :: msg_len = 512
end module kinds
