!> Gauss-Legendre rules on [-1, 1] and their tensor products on the square.
!> Section 2.3 of the paper: 3x3 points for the membrane, bending and inertia
!> terms, 2x2 for the transverse shear (selective reduced integration).
module gauss_rules
   use kinds, only: dp
   implicit none
   private
   public :: gauss_1d, gauss_2d, gauss_legendre, max_gauss_order

   !> Highest number of points per direction tabulated here.
   integer, parameter :: max_gauss_order = 4

contains

   !> Points and weights of the n-point Gauss-Legendre rule, 1 <= n <= 4
   !> (Abramowitz & Stegun, Table 25.4). Any other n gives zero weights.
   pure subroutine gauss_1d(n, xi, w)
      integer, intent(in) :: n          !< number of points
      real(dp), intent(out) :: xi(n)    !< abscissae in [-1, 1]
      real(dp), intent(out) :: w(n)     !< weights, summing to 2
      real(dp), parameter :: a3 = 0.774596669241483377035853079956480_dp   ! sqrt(3/5)
      real(dp), parameter :: a2 = 0.577350269189625764509148780501957_dp   ! 1/sqrt(3)
      real(dp), parameter :: a4i = 0.339981043584856264802665759103245_dp
      real(dp), parameter :: a4o = 0.861136311594052575223946488892809_dp
      real(dp), parameter :: w4i = 0.652145154862546142626936050778001_dp
      real(dp), parameter :: w4o = 0.347854845137453857373063949221999_dp
      select case (n)
      case (1); xi = [0.0_dp];          w = [2.0_dp]
      case (2); xi = [-a2, a2];         w = [1.0_dp, 1.0_dp]
      case (3); xi = [-a3, 0.0_dp, a3]; w = [5.0_dp, 8.0_dp, 5.0_dp]/9.0_dp
      case (4); xi = [-a4o, -a4i, a4i, a4o]; w = [w4o, w4i, w4i, w4o]
      case default; xi = 0.0_dp;            w = 0.0_dp
      end select
   end subroutine gauss_1d

   !> The n x n product rule on the square [-1,1]^2; point k = i + n (j-1)
   !> lies at (xi_i, eta_j), so xi runs fastest.
   pure subroutine gauss_2d(n, pts, w)
      integer, intent(in) :: n              !< points per direction
      real(dp), intent(out) :: pts(2, n*n)  !< (xi, eta) of each point
      real(dp), intent(out) :: w(n*n)       !< weights, summing to 4
      real(dp) :: x(n), wx(n)
      integer :: i, j
      call gauss_1d(n, x, wx)
      pts(1, :) = [((x(i), i = 1, n), j = 1, n)]
      pts(2, :) = [((x(j), i = 1, n), j = 1, n)]
      w = [((wx(i)*wx(j), i = 1, n), j = 1, n)]
   end subroutine gauss_2d

   !> The n-point Gauss-Legendre rule on [-1, 1] for any n >= 1, by the Golub-Welsch algorithm:
   !> the abscissae are the eigenvalues of the symmetric tridiagonal Jacobi matrix of the
   !> Legendre polynomials (off-diagonal k/sqrt(4k^2 - 1)), the weights 2 v_1^2 from the first
   !> components of its normalised eigenvectors (LAPACK dstev).
   subroutine gauss_legendre(n, xi, w, stat)
      integer, intent(in) :: n          !< number of points, >= 1
      real(dp), intent(out) :: xi(n)    !< abscissae, increasing
      real(dp), intent(out) :: w(n)     !< weights, summing to 2
      integer, intent(out) :: stat      !< 0, or LAPACK's info
      interface
         subroutine dstev(jobz, n, d, e, z, ldz, work, info)
            import :: dp
            character, intent(in) :: jobz
            integer, intent(in) :: n, ldz
            real(dp), intent(inout) :: d(*), e(*)
            real(dp), intent(out) :: z(ldz, *), work(*)
            integer, intent(out) :: info
         end subroutine dstev
      end interface
      real(dp) :: off(max(n - 1, 1)), z(n, n), work(max(2*n - 2, 1))
      integer :: k
      xi = 0.0_dp
      off(:n - 1) = [(real(k, dp)/sqrt(4.0_dp*real(k, dp)**2 - 1.0_dp), k = 1, n - 1)]
      call dstev('V', n, xi, off, z, n, work, stat)
      w = 2.0_dp*z(1, :)**2
   end subroutine gauss_legendre

end module gauss_rules
