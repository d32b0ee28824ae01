!> Modal analysis (`&analysis kind = 'modes'`): the lowest `&modes count`
!> natural frequencies and mode shapes of the plate,
!>     K_L phi = omega^2 M phi,     phi^T M phi = 1,
!> with K_L and M the banded matrices of the impact analysis (eq. 15; the consistent mass with
!> rotary inertia, Appendix B): small vibrations about the flat plate in either theory. Solver
!> (LAPACK dsbgvx), free edges and the split of each mode's kinetic energy: above modal_solve.
!> More: docs/ANALYSES.md.
module modal_analysis
   use kinds, only: dp, pi, msg_len
   use plate_model, only: model_t
   use global_matrix, only: global_matvec
   use mesh, only: ndof_node
   implicit none
   private
   public :: modal_result_t, modal_solve

   !> Natural frequencies and modes.
   type :: modal_result_t
      integer :: count = 0                      !< modes computed
      real(dp), allocatable :: omega2(:)        !< eigenvalues omega^2 (rad^2/s^2), ascending
      real(dp), allocatable :: freq(:)          !< frequencies sign(omega^2) sqrt|omega^2|/(2 pi) (Hz)
      real(dp), allocatable :: shapes(:,:)      !< (neq, count) modes, phi^T M phi = 1
      real(dp), allocatable :: fraction(:,:)    !< (3, count) kinetic energy share of w; u, v; psi_x, psi_y
   end type modal_result_t

   ! LAPACK: selected eigenpairs of a generalized symmetric-definite band problem.
   interface
      subroutine dsbgvx(jobz, range, uplo, n, ka, kb, ab, ldab, bb, ldbb, q, ldq, vl, vu, il, iu, &
                        abstol, m, w, z, ldz, work, iwork, ifail, info)
         import :: dp
         character, intent(in) :: jobz, range, uplo
         integer, intent(in) :: n, ka, kb, ldab, ldbb, ldq, il, iu, ldz
         real(dp), intent(inout) :: ab(ldab, *), bb(ldbb, *)
         real(dp), intent(out) :: q(ldq, *)
         real(dp), intent(in) :: vl, vu, abstol
         integer, intent(out) :: m
         real(dp), intent(out) :: w(*), z(ldz, *), work(*)
         integer, intent(out) :: iwork(*), ifail(*), info
      end subroutine dsbgvx
   end interface

contains

   !> Solver: LAPACK dsbgvx on K_L and M in band storage (LAPACK's layout, uplo = 'U'),
   !> eigenpairs 1..count; with the shapes it keeps an n x n matrix (8 n^2 bytes,
   !> time ~ n^2 kd), without them time ~ n kd^2. Free edges: K_L is singular, M is not;
   !> rigid-body modes give omega^2 ~ 0. Each mode's kinetic energy is split between w, u, v
   !> and psi_x, psi_y (summing to 1 for a symmetric laminate).
   !>
   !> The lowest `count` eigenpairs of K_L phi = omega^2 M phi (band storage).
   subroutine modal_solve(model, count, vectors, res, stat, errmsg)
      type(model_t), intent(in) :: model           !< model: K_L and M in band storage
      integer, intent(in) :: count                 !< modes wanted, 1..neq
      logical, intent(in) :: vectors               !< also the modes (res%shapes, res%fraction)
      type(modal_result_t), intent(out) :: res     !< frequencies, and modes when asked for
      integer, intent(out) :: stat                 !< 0 on success
      character(len=*), intent(inout) :: errmsg    !< reason on failure
      real(dp), allocatable :: ab(:,:), bb(:,:), q(:,:), w(:), work(:), part(:), mpart(:)
      integer, allocatable :: iwork(:), ifail(:), kind_of(:)
      integer :: n, kd, found, info, j, k, c, nq
      integer, parameter :: w_dof = 3
      character :: jobz
      character(len=msg_len) :: msg
      stat = 0
      n = model%msh%neq
      if (trim(model%stiff%storage) /= 'band' .or. trim(model%mass%storage) /= 'band') then
         stat = 1
         errmsg = "modes: K_L and M must be in band storage (&analysis storage = 'band')"
         return
      end if
      if (count < 1 .or. count > n) then
         stat = 1
         write (errmsg, '(a,i0,a,i0,a)') '&modes: count = ', count, ': must be in 1..', n, &
            ' (the number of equations)'
         return
      end if
      kd = model%stiff%band%kd
      allocate (ab, source=model%stiff%band%ab)
      allocate (bb, source=model%mass%band%ab)
      ! without the vectors dsbgvx references neither Q nor Z
      jobz = merge('V', 'N', vectors)
      nq = merge(n, 1, vectors)
      allocate (q(nq, nq), w(n), res%shapes(nq, merge(count, 1, vectors)), work(7*n), iwork(5*n), ifail(n), &
                stat=info, errmsg=msg)
      if (info /= 0) then
         stat = 1
         write (errmsg, '(a,i0,a)') 'modes: cannot allocate the ', n, ' x n work matrix of dsbgvx: ' // trim(msg) &
            // ' (&modes shapes = .false. computes the frequencies alone)'
         return
      end if
      call dsbgvx(jobz, 'I', 'U', n, kd, kd, ab, kd + 1, bb, kd + 1, q, nq, 0.0_dp, 0.0_dp, 1, count, &
                  2.0_dp*tiny(1.0_dp), found, w, res%shapes, nq, work, iwork, ifail, info)
      if (info /= 0 .or. found /= count) then
         stat = 1
         if (info < 0) then
            write (errmsg, '(a,i0)') 'modes: dsbgvx rejected argument ', -info
         else if (info > n) then
            write (errmsg, '(a,i0,a)') 'modes: the mass matrix is not positive definite (dsbgvx: leading minor ', &
               info - n, ')'
         else
            write (errmsg, '(a,i0,a,i0,a)') 'modes: dsbgvx: ', info, ' eigenvectors did not converge (', &
               found, ' eigenvalues found)'
         end if
         return
      end if

      res%count = count
      res%omega2 = w(:count)
      res%freq = sign(sqrt(abs(res%omega2)), res%omega2)/(2.0_dp*pi)
      if (.not. vectors) then
         deallocate (res%shapes)
         return
      end if

      ! -- kinetic energy share of each kind of freedom, the columns: 1 w; 2 u, v; 3 psi
      allocate (kind_of(n), part(n), mpart(n), res%fraction(3, count))
      kind_of = 0
      do k = 1, ndof_node
         kind_of(pack(model%msh%eq(k, :), model%msh%eq(k, :) > 0)) = &
            merge(2, merge(1, 3, k == w_dof), k <= 2)
      end do
      modes: do j = 1, count
         do c = 1, 3
            part = merge(res%shapes(:, j), 0.0_dp, kind_of == c)
            call global_matvec(model%mass, part, mpart)
            res%fraction(c, j) = dot_product(part, mpart)
         end do
      end do modes
   end subroutine modal_solve

end module modal_analysis
