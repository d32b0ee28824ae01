!> What the program says on the terminal before any work: the usage
!> (impact --help) and the other options' answers, the notice of a large
!> mesh the program chose, and the echo of the run (after Bathe's STAP: every
!> value of the deck with its symbol and unit, the derived sizes, the
!> laminate, and the scene report of src/model/scene_model.f90).
module run_report
   use kinds, only: dp
   use build_info, only: code_version
   use number_text, only: int_str, real_short
   use deck_schema, only: deck_t, deck_groups, is_given, strength_given, toughness_given
   use deck_echo, only: echo_deck, write_schema, write_deck_table
   use input_deck, only: model_size
   use storage_choice, only: resolve_storage
   use progress_line, only: duration_text
   use plate_model, only: model_t
   use global_matrix, only: global_bandwidth, global_stored_entries
   use scene_model, only: write_scene_report
   use delamination, only: write_delamination_scene
   implicit none
   private
   public :: echo_model, write_answer, usage_line, say_large_chosen_mesh

   !> The usage in one line (impact --help's first; after a wrong command line).
   character(len=*), parameter :: usage_line = 'usage: impact [options] [deck.nml]'

contains

   !> The echo of the effective input and the derived sizes.
   subroutine echo_model(deck, model, u)
      type(deck_t), intent(in) :: deck      !< the effective deck
      type(model_t), intent(in) :: model    !< the model built from it
      integer, intent(in) :: u              !< open formatted unit
      write (u, '(a)') 'impact: low-velocity impact of a composite laminate (Choi, Hong & Lee 1991)'
      call echo_deck(deck, u, '')
      write (u, '(a,i0,a,i0,a,i0,a,i0,a,i0)') 'model: nodes ', model%msh%nnode, ', elements ', &
         model%msh%nelem, ', equations ', model%msh%neq, ', half-bandwidth ', &
         global_bandwidth(model%mass), ', stored entries ', global_stored_entries(model%mass)
      write (u, '(a)') 'model: transverse shear ' // trim(model%shear_rule) // ', contact load ' // deck%contact_load
      write (u, '(a,3es12.4)') 'laminate: A11 A22 A66 (N/m)  ', model%lmt%a(1,1), model%lmt%a(2,2), model%lmt%a(3,3)
      write (u, '(a,4es12.4)') 'laminate: D11 D22 D66 D16 (N m) ', model%lmt%d(1,1), model%lmt%d(2,2), &
         model%lmt%d(3,3), model%lmt%d(1,3)
      write (u, '(a,2es12.4)') 'laminate: Abar44 Abar55 (N/m) ', model%lmt%as(1,1), model%lmt%as(2,2)
      write (u, '(a,3es12.4)') 'laminate: P (kg/m^2), R (kg/m), I (kg) ', model%lmt%p, model%lmt%r, model%lmt%i
      call write_scene_report(model%scene, u)
      call write_delamination_scene(u, model%lmt%d, model%scene%impactor_mass, model%scene%plate_mass, &
         is_given(deck, 'strength', 'g2c'), deck%g2c, strength_given(deck) .or. toughness_given(deck))
   end subroutine echo_model

   !> impact --help: the usage, the options and the deck's groups.
   subroutine usage(u)
      integer, intent(in) :: u              !< open formatted unit
      integer :: g
      write (u, '(a/)') usage_line // '      (no deck: the deck is read from standard input)'
      write (u, '(a/)') 'Nonlinear low-velocity impact of a composite laminate (Choi, Hong & Lee 1991).'
      write (u, '(a)') 'options:'
      write (u, '(a)') '  --check              read, echo, build and factor; stop before the time loop (a data check)'
      write (u, '(a)') '  --overwrite          replace the results of an earlier run with the same prefix'
      write (u, '(a)') '  --restart            continue the run at the deck''s prefix from its last restart point'
      write (u, '(a)') '  --set group.var=val  set a deck variable after reading the deck (repeatable); the deck is'
      write (u, '(a)') '                       then checked once with all: --set analysis.dt=1e-6 --set mesh.nx=18'
      write (u, '(a)') '  --trace STEP[,STEP]  print every box of the flowchart (Fig. 3) for those time steps'
      write (u, '(a)') '  --accuracy TOL       every result with its error bar, refined to relative error TOL (&accuracy)'
      write (u, '(a)') '  --single             one run of the deck, its &accuracy target left aside'
      write (u, '(a)') '  --schema             the deck''s variables as tab-separated lines (for tools)'
      write (u, '(a)') '  --deck-table         the deck''s variables as the Markdown table of docs/DECK.md'
      write (u, '(a)') '  --version            the version this program was built from'
      write (u, '(a)') '  --help               this text'
      write (u, '(a/)') 'options may stand before or after the deck; one deck only'
      write (u, '(a,*(:," &",a))') 'deck groups:', (trim(deck_groups(g)), g = 1, size(deck_groups))
      write (u, '(a)') 'every variable, its unit, default and meaning: docs/DECK.md, "The deck" (or impact --deck-table);'
      write (u, '(a/)') 'installed (make install): the documents in <prefix>/share/doc/impact ' &
         // '(docs/DECK.md there)'
      write (u, '(a)') 'Report bugs to the impact developers, with the deck, the command line and the first line'
      write (u, '(a)') 'of impact --version (README.md, "Reporting bugs").'
   end subroutine usage

   !> A mesh the program chose of more than large_model equations: said before
   !> the set-up, with its size, its memory and, in sparse storage, the set-up's
   !> estimated cpu time (set_up_s, scaled by the equations^set_up_growth).
   subroutine say_large_chosen_mesh(deck, unit)
      type(deck_t), intent(in) :: deck              !< the deck, nx and ny given or chosen
      integer, intent(in) :: unit                   !< where it is said (standard output)
      real(dp), parameter :: large_model = 1.0e5_dp, set_up_neq = 94605.0_dp, set_up_s = 4.8_dp, &
                             set_up_growth = 1.3_dp
      real(dp) :: neq, memory
      character(len=:), allocatable :: time
      if (len_trim(deck%mesh_chosen) == 0) return
      call model_size(deck, neq, memory)
      if (neq <= large_model) return
      time = ''
      if (resolve_storage(deck%storage, nint(min(neq, 1.0e9_dp)), .false.) == 'sparse') time = ' and about ' &
         // duration_text(set_up_s*(neq/set_up_neq)**set_up_growth) // ' of set-up on one core'
      write (unit, '(a)') 'mesh chosen: ' // int_str(deck%nx) // ' x ' // int_str(deck%ny) &
         // ' elements, about ' // int_str(nint(neq)) // ' equations, ' // real_short(memory/1024.0_dp**3) &
         // ' GiB for the matrices' // time // ': give &mesh nx, ny for a coarser mesh'
      flush (unit)
   end subroutine say_large_chosen_mesh

   !> The answer of --help, --version, --schema, --deck-table; nothing for 'run'.
   subroutine write_answer(action, u)
      character(len=*), intent(in) :: action     !< 'help', 'version', 'schema', 'deck-table' or 'run'
      integer, intent(in) :: u                   !< open formatted unit
      select case (action)
      case ('help');       call usage(u)
      case ('version')     ! the version in one line (scripts read it), the copyright, the licence
         write (u, '(a)') code_version, 'Copyright (c) 2026 the impact developers.', &
            'License MIT: <https://opensource.org/licenses/MIT>, the file LICENSE.', &
            'This is free software: you are free to change and redistribute it.', &
            'There is NO WARRANTY, to the extent permitted by law.'
      case ('schema');     call write_schema(u)
      case ('deck-table'); call write_deck_table(u)
      end select
   end subroutine write_answer

end module run_report
