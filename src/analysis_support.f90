!> What the static, modal and pressure analyses share (`&analysis kind =
!> 'static' | 'modes' | 'pressure'`): the load vector of `&load` and the
!> result files.
!>
!> Loads (`&load kind`), w positive the way the impactor moves:
!>  - 'uniform':       q = q0 over the whole plate (Pa);
!>  - 'sinusoidal':    q = q0 cos(pi x/a) cos(pi y/b), x, y measured from the
!>                     plate centre: q0 sin(pi X/a) sin(pi Y/b) with X, Y from
!>                     a corner, the single Navier term (Pa);
!>  - 'central_force': a force P at the plate centre (N).
!> Pressures are integrated consistently, f_i = int phi_i q dA, element by
!> element (element_pressure_load); on a quarter (or strip) model the load
!> vector is the modelled part's share, and a central force enters as
!> P / sym_factor, as the contact force does.
!>
!> Result files are column text: a title line, the deck echo, one line per
!> column with its unit, then the column names on one '#' line. As for the
!> impact analysis (output_files, check_output), a run refuses to replace
!> the result files of an earlier run unless &output overwrite = .true.
!> (or impact --overwrite): check_result_files, before any work.
module analysis_support
   use kinds, only: dp, pi, msg_len
   use input_deck, only: deck_t, echo_deck
   use impact_driver, only: model_t, gather_element, scatter_add_element
   use element_matrices, only: element_pressure_load, ngp_full
   use mesh, only: nfe
   implicit none
   private
   public :: assemble_load, check_result_files, open_result_file

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
            if (deck%load_kind == 'uniform') then
               q = deck%load_magnitude
            else
               q = deck%load_magnitude*cos(pi*model%geo(e)%xy3(1, :)/deck%a) &
                                      *cos(pi*model%geo(e)%xy3(2, :)/deck%b)
            end if
            call element_pressure_load(model%geo(e), q, fe)
            call scatter_add_element(model%msh%elem_eq(:, e), fe, f)
         end do elements
      case ('central_force')
         f(model%eq_impact) = model%force_share*deck%load_magnitude
      case default
         stat = 1
         errmsg = '&load: kind = '''//trim(deck%load_kind)//''': unknown load'
      end select
   end subroutine assemble_load

   !> Before any work: refuses when <prefix><suffix> exists for one of the
   !> suffixes, the results of an earlier run, unless deck%overwrite.
   subroutine check_result_files(deck, suffixes, stat, errmsg)
      type(deck_t), intent(in) :: deck            !< effective deck (prefix, overwrite)
      character(len=*), intent(in) :: suffixes(:) !< file names after the prefix
      integer, intent(out) :: stat                !< 0 when the run may write its results
      character(len=*), intent(inout) :: errmsg   !< reason on failure
      logical :: exists
      integer :: i
      stat = 0
      if (deck%overwrite) return
      files: do i = 1, size(suffixes)
         inquire (file=trim(deck%prefix)//trim(suffixes(i)), exist=exists)
         if (exists) then
            stat = 1
            errmsg = trim(deck%source)//": &output: prefix = '"//trim(deck%prefix)//"': "// &
               trim(deck%prefix)//trim(suffixes(i))//' exists, the results of another run: '// &
               'choose another prefix, or set overwrite = .true. in &output (or run impact --overwrite) '// &
               'to replace them'
            return
         end if
      end do files
   end subroutine check_result_files

   !> Creates the directory of the path if needed, opens it and writes the
   !> header: title, deck echo, the columns with their units, the names.
   subroutine open_result_file(deck, suffix, title, names, texts, unit, path, stat, errmsg)
      type(deck_t), intent(in) :: deck            !< effective deck (echoed; prefix)
      character(len=*), intent(in) :: suffix      !< file name after the prefix, e.g. '_static.dat'
      character(len=*), intent(in) :: title       !< first line, after '# '
      character(len=*), intent(in) :: names(:)    !< column names (with their unit)
      character(len=*), intent(in) :: texts(:)    !< column meanings (with their unit)
      integer, intent(out) :: unit                !< the open file
      character(len=*), intent(out) :: path       !< its path
      integer, intent(out) :: stat                !< 0 on success
      character(len=*), intent(inout) :: errmsg   !< reason on failure
      character(len=msg_len) :: iomsg
      integer :: c, slash, ex

      path = trim(deck%prefix)//suffix
      slash = index(path, '/', back=.true.)
      if (slash > 1) call execute_command_line('mkdir -p "'//path(1:slash-1)//'"', exitstat=ex)
      open (newunit=unit, file=path, status='replace', action='write', iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         errmsg = '&output: prefix = "'//trim(deck%prefix)//'": cannot write '//trim(path)//': '//trim(iomsg)
         return
      end if
      write (unit, '(a)') '# '//title
      call echo_deck(deck, unit, '# ')
      write (unit, '(a)') '# columns:'
      do c = 1, size(names)
         write (unit, '(a,i2,1x,a,1x,a)') '# ', c, names(c), trim(texts(c))
      end do
      write (unit, '(a)', advance='no') '#'
      do c = 1, size(names)
         write (unit, '(1x,a)', advance='no') trim(names(c))
      end do
      write (unit, '(a)') ''
   end subroutine open_result_file

end module analysis_support
