!> The load vector of `&load` for the static and pressure analyses, w positive the way the
!> impactor moves: 'uniform' q = q0 (Pa); 'sinusoidal' q = q0 cos(pi x/a) cos(pi y/b), x, y
!> from the centre (the single Navier term); 'central_force' P (N). Pressures are integrated
!> consistently, f_i = int phi_i q dA; a symmetric model takes its share (P / sym_factor).
module analysis_load
   use kinds, only: dp, pi, msg_len
   use deck_schema, only: deck_t
   use plate_model, only: model_t, scatter_add_element
   use element_matrices, only: element_pressure_load, ngp_full
   use mesh, only: nfe
   implicit none
   private
   public :: assemble_load

contains

   !> The load vector of `&load` for the model (N), at load factor 1.
   subroutine assemble_load(deck, model, f, stat, errmsg)
      type(deck_t), intent(in) :: deck           !< deck: load kind, magnitude, plate size
      type(model_t), intent(in) :: model         !< model
      real(dp), intent(out) :: f(:)              !< load vector, size neq (N)
      integer, intent(out) :: stat               !< 0 on success
      character(len=*), intent(inout) :: errmsg  !< reason on failure
      real(dp) :: q(ngp_full), fe(nfe)
      integer :: e
      stat = 0
      f = 0.0_dp
      select case (deck%load_kind)
      case ('uniform', 'sinusoidal')
         elements: do e = 1, model%msh%nelem
            q = deck%load_magnitude
            if (deck%load_kind == 'sinusoidal') q = q*cos(pi*model%geo(e)%xy3(1, :)/deck%a) &
                                                      *cos(pi*model%geo(e)%xy3(2, :)/deck%b)
            call element_pressure_load(model%geo(e), q, fe)
            call scatter_add_element(model%msh%elem_eq(:, e), fe, f)
         end do elements
      case ('central_force'); f(model%eq_impact) = model%force_share*deck%load_magnitude
      case default
         stat = 1
         errmsg = '&load: kind = '''//trim(deck%load_kind)//''': unknown load'
      end select
   end subroutine assemble_load

end module analysis_load
