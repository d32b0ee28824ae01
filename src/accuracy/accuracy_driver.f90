!> An accuracy run, `impact --accuracy TOL deck.nml` (docs/ACCURACY.md): dt and the mesh refined
!> the cheapest way until the results targeted are within TOL or the cap stops it. 1. the runs
!> (accuracy_runs); 2. the errors (accuracy_ladder); 3. the cheapest run that meets the target,
!> else an axis refined; 4. the models compared (model_comparison); 5. the report:
!> <prefix>_summary.dat (the run chosen's summary, then the accuracy's keys), <prefix>_accuracy.dat
!> (a row per run, the axes' estimates as '#' lines: postproc/accuracy.gp), a few terminal lines.
!> A stop signal keeps the runs done; --restart continues. Exit status 0 when met, exit_not_met
!> (3) when not, 128 + N after signal N.
module accuracy_driver
   use, intrinsic :: iso_fortran_env, only: int64, error_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use kinds, only: dp, msg_len
   use deck_schema, only: deck_t, strength_given, find_var
   use deck_echo, only: echo_deck
   use command_line, only: options_t
   use number_text, only: int_str, real_short
   use plate_model, only: model_t, build_model
   use mesh, only: mesh_t
   use scene_settings, only: settings_t, scene_settings_of
   use file_system, only: make_directories, path_kind, path_regular, file_size, remove_file, &
      file_lock_t, lock_file, unlock_file
   use result_files, only: results_claim_t, claim_results, release_results, summary_item_t, &
      summary_real, summary_integer, summary_text, write_summary_file, write_column_block
   use result_reader, only: summary_t, read_summary
   use child_process, only: program_path, usable_cpus, pass_stops_to_children, stop_caught
   use accuracy_runs, only: run_t, launcher_t, nq, result_keys, result_units, run_planned, &
      state_planned, state_done, state_failed, state_skipped, predicted_run_cost, ladder_name, &
      error_scale, iq_failure, iq_peak_time, is_ladder
   use accuracy_ladder, only: ladder_t, axis_t, judged_t, choice_t, build_axes, judge_run, &
      choose_run, final_run, ladder_run, time_partner, cross_needed, done_run
   use model_comparison, only: comparison_t, compare_models, comparison_report, relative
   implicit none
   private
   public :: run_accuracy, ladder_mesh, targeted_results

   type :: accuracy_outcome_t
      logical :: met = .false.
      character(len=240) :: status = ''            !< 'met', 'cap reached: ...', 'not met: ...', 'stopped ...'
      integer :: stop_signal = 0                   !< 0: none
      integer :: chosen = 0                        !< the run whose results are given
      type(judged_t) :: jd                         !< its results and errors
      real(dp) :: wall_s = 0.0_dp
      type(comparison_t) :: cmp(2)                 !< the models compared
   end type accuracy_outcome_t

   integer, parameter :: exit_not_met = 3
   !> The files of the prefix an accuracy run claims: its own, then a plain run's, removed.
   character(len=*), parameter :: own_files(6) = [character(len=16) :: '_accuracy.dat', '_summary.dat', &
      '_history.dat', '.h5', '.xdmf', '.restart']
   !> The ladder's limits: time levels, mesh levels, the smallest dt, the most elements.
   integer, parameter :: max_time_levels = 11, max_mesh_levels = 12, max_elements = 10000
   real(dp), parameter :: min_dt = 1.0e-10_dp                  ! s
   !> The cap when the deck gives none, in runs of level 0 (docs/ACCURACY.md: why).
   integer, parameter :: default_cap_times = 100
   !> Levels of the time and the mesh axis at the start: a third mesh level, the dearest run,
   !> only when the two-level estimate (Roache's Fs = 3) does not meet the target.
   integer, parameter :: first_levels(2) = [3, 2]
   real(dp), parameter :: ladder_grading = 1.25_dp             ! ratio of neighbouring elements (-)
   !> A run's state as a word (state_planned, ... of accuracy_runs).
   character(len=7), parameter :: state_words(0:5) = [character(len=7) :: 'planned', 'planned', 'done', &
      'failed', 'skipped', 'stopped']

contains

   !> The accuracy run of the deck (module header).
   subroutine run_accuracy(opts, deck, unit, exit_code, stat, errmsg)
      type(options_t), intent(in) :: opts
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: unit                   !< standard output
      integer, intent(out) :: exit_code, stat       !< 0 met, exit_not_met, 128 + N after N; 0 or 1
      character(len=*), intent(inout) :: errmsg
      type(results_claim_t) :: claim
      type(launcher_t) :: la
      type(ladder_t) :: lad
      type(accuracy_outcome_t) :: out
      type(deck_t) :: base, claimed                 ! level 0's mesh (ladder_mesh); overwriting with --restart
      integer(int64) :: wall0, wall1, rate
      integer :: i, ignored
      type(file_lock_t) :: lock
      character(len=msg_len) :: iomsg
      exit_code = 1;  stat = 1
      call system_clock(wall0, rate)
      if (len(opts%deck_path) == 0) errmsg = '--accuracy: give the deck as a file (its runs read it again), ' // &
         'not on standard input'
      if (deck%analysis_kind /= 'impact') errmsg = deck%source // ": &accuracy: target needs &analysis kind = 'impact'"
      if (deck%analysis_kind /= 'impact' .or. len(opts%deck_path) == 0) return
      call pass_stops_to_children()                 ! a stop ends the runs going, keeps those done
      claimed = deck;  claimed%overwrite = deck%overwrite .or. opts%restart
      associate (path => deck%prefix // trim(own_files(1)))   ! a run killed before it wrote: its claim
      i = 1
      if (path_kind(path) == path_regular) then
         if (file_size(path) == 0) call lock_file(path, lock, i, iomsg)
      end if
      if (i == 0) call remove_file(path, ignored)              ! i /= 0: not empty, or a run holds it
      if (i == 0) call unlock_file(lock)
      end associate
      call claim_results(claimed, own_files, claim, stat, errmsg)
      if (stat /= 0) return
      do i = 3, size(own_files)                     ! a plain run's files: not the run chosen's
         call remove_file(deck%prefix // trim(own_files(i)), ignored)
      end do
      call set_up(opts, deck, unit, base, la, lad, stat, errmsg)
      if (stat == 0) call climb(base, la, lad, out, stat, errmsg)
      if (stat == 0 .and. stop_caught() == 0) call compare_models(base, la, lad, out%chosen, out%cmp, stat, errmsg)
      if (stat == 0 .and. stop_caught() /= 0) then
         out%status = 'stopped by signal ' // int_str(stop_caught()) // ': the results carry the errors reached; ' // &
                      'impact --restart continues the ladder'
         out%met = .false.;  out%stop_signal = stop_caught()
         out%cmp%what = ['theory    ', 'bend_twist']
         where (out%cmp%run == 0 .and. len_trim(out%cmp%note) == 0) out%cmp%note = 'the run was stopped'
      end if
      call system_clock(wall1)
      out%wall_s = real(wall1 - wall0, dp)/real(rate, dp)
      if (stat == 0 .and. out%chosen > 0) call write_accuracy_table(deck, lad, out, stat, errmsg)
      if (stat == 0 .and. out%chosen > 0) call report(deck, la, lad, out, unit, stat, errmsg)
      call release_results(claim, discard=stat /= 0 .or. out%chosen == 0)
      if (stat == 0) exit_code = merge(0, exit_not_met, out%met)
      if (stop_caught() /= 0) exit_code = 128 + stop_caught()
      if (stat == 0 .and. out%chosen == 0) write (error_unit, '(a)') 'impact: stopped by signal ' // &
         int_str(stop_caught()) // ' before the first run of the ladder ended: no results written'
   end subroutine run_accuracy

   !> The launcher, the scene of the deck's model, level 0's mesh and the first levels planned.
   subroutine set_up(opts, deck, unit, base, la, lad, stat, errmsg)
      type(options_t), intent(in) :: opts
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: unit                   !< standard output
      type(deck_t), intent(out) :: base             !< the deck with level 0's mesh
      type(launcher_t), intent(out) :: la
      type(ladder_t), intent(out) :: lad            !< the first levels planned, the finest allowed
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      type(model_t) :: model
      character(len=msg_len) :: iomsg
      character(len=:), allocatable :: why, cap
      integer :: l
      call build_model(deck, model, stat, errmsg)
      if (stat /= 0) return
      la%scene = model%scene;  la%theory = la%scene%theory;  la%exe = program_path();  la%cpus = usable_cpus()
      la%deck_path = opts%deck_path;  la%user_settings = opts%settings;  la%restart = opts%restart
      la%dir = deck%prefix // '_acc/';  la%every_step = strength_given(deck)
      if (deck%given(find_var('accuracy', 'max_cpu_s'))) la%cap = deck%accuracy_max_cpu_s
      if (.not. deck%given(find_var('accuracy', 'max_cpu_s'))) la%cap_times = default_cap_times
      la%gauge = model%gauge_xy;  la%unit = unit    ! the strain at one point on every mesh
      base = deck;  la%impact_element = la%scene%element_size
      call ladder_mesh(deck, model%msh, base, la%impact_element, why)
      la%n0 = base%nx*base%ny
      call make_directories(la%dir(:len(la%dir) - 1), stat, iomsg)
      if (stat /= 0) errmsg = deck%source // ": &output: prefix = '" // deck%prefix // "': " // trim(iomsg)
      if (stat /= 0) return
      cap = int_str(default_cap_times) // ' times the first run''s cpu time'
      if (la%cap_times == 0) cap = real_short(la%cap) // ' s of cpu'
      write (unit, '(a)') 'accuracy: target ' // real_short(deck%accuracy_target) // ' (relative), cap ' // &
         cap // ', ' // int_str(la%cpus) // ' runs at a time; theory ' // &
         trim(la%theory) // ', domain ' // trim(la%scene%domain) // '; runs in ' // la%dir
      if (len(why) > 0) write (unit, '(a)') 'accuracy: ' // why
      allocate (lad%runs(0))
      do l = 0, maxval(first_levels) - 1
         if (l < first_levels(1)) call plan(lad%runs, base, la, l, 0)
         if (l > 0 .and. l < first_levels(2)) call plan(lad%runs, base, la, 0, l)
      end do
      lad%target = deck%accuracy_target
      lad%k_max = min(max_time_levels - 1, exponent(deck%dt/min_dt) - 1)   ! dt0/2^k_max >= min_dt
      call targeted_results(deck, lad%targeted, stat, errmsg)
   end subroutine set_up

   !> Level 0's mesh: the deck's, unless the deck gives no &mesh grading and its element at the
   !> impact point is larger than the Hertz radius a: then graded by ladder_grading, the counts
   !> raised until that element is at most a (or, with no raising, the least grading that does).
   !> Why: docs/PERFORMANCE.md, level 0 graded.
   subroutine ladder_mesh(deck, msh, base, impact_element, why)
      type(deck_t), intent(in) :: deck
      type(mesh_t), intent(in) :: msh               !< the deck's mesh
      type(deck_t), intent(inout) :: base           !< the deck, its nx, ny, grading level 0's
      real(dp), intent(inout) :: impact_element(2)  !< sides of level 0's element at the impact point (m)
      character(len=:), allocatable, intent(out) :: why   !< what was chosen and why, '' for the deck's mesh
      type(settings_t) :: est
      real(dp) :: a, side(2), counted(2), g, lo, mid
      integer :: n(2), it
      why = ''
      est = scene_settings_of(deck)
      a = est%contact_radius
      if (deck%given(find_var('mesh', 'grading')) .or. maxval(impact_element) <= a) return
      ! each direction: the longer side from the impact point, the share of the count across it
      side = [max(msh%x1 - msh%x_impact, msh%x_impact - msh%x0), max(msh%y1 - msh%y_impact, msh%y_impact - msh%y0)]
      counted = real(nint(side/impact_element), dp)/real([deck%nx, deck%ny], dp)
      ! the counts that bring the element at the impact point to a with ladder_grading
      n = max([deck%nx, deck%ny], ceiling(log(1.0_dp + side*(ladder_grading - 1.0_dp)/a)/log(ladder_grading)/counted &
                                          - 1.0e-9_dp))
      ! the deck's counts already do with ladder_grading: the least grading that does (bisection)
      g = ladder_grading
      lo = 1.0_dp
      do it = 1, merge(60, 0, all(n == [deck%nx, deck%ny]))   ! none when the counts were raised
         mid = 0.5_dp*(lo + g)
         if (maxval(first_element(mid)) <= a) g = mid
         if (g /= mid) lo = mid
      end do
      impact_element = first_element(g)
      base%nx = n(1);  base%ny = n(2);  base%grading = g
      why = 'level 0: ' // int_str(base%nx) // ' x ' // int_str(base%ny) // ' graded by ' // &
         real_short(g) // ' (the element at the impact point ' // &
         real_short(maxval(impact_element)*1.0e3_dp) // ' mm, the Hertz radius ' // real_short(a*1.0e3_dp) // &
         ' mm; the deck''s ' // int_str(deck%nx) // ' x ' // int_str(deck%ny) // ' does not resolve it, and ' // &
         'gives no &mesh grading)'
   contains
      !> The sides of the element at the impact point with grading gg: side (g - 1)/(g^m - 1).
      pure function first_element(gg) result(e)
         real(dp), intent(in) :: gg
         real(dp) :: e(2)
         e = side*(gg - 1.0_dp)/(gg**(counted*real(n, dp)) - 1.0_dp)
      end function first_element
   end subroutine ladder_mesh

   !> Plans the ladder run (k, j) unless it is there (one the cap turned away: again). A graded
   !> mesh is refined as one family: the grading g0^(nx0/nx) keeps its largest over its smallest.
   subroutine plan(runs, deck, la, k, j)
      type(run_t), allocatable, intent(inout) :: runs(:)
      type(deck_t), intent(in) :: deck              !< the deck (level 0)
      type(launcher_t), intent(in) :: la            !< the launcher (the element at the impact point, level 0)
      integer, intent(in) :: k, j                   !< time and mesh level
      type(run_t) :: r
      integer :: i
      i = ladder_run(runs, k, j)
      if (i > 0) runs(i)%state = merge(state_planned, runs(i)%state, runs(i)%state == state_skipped)
      if (i > 0) return
      r%k = k;  r%j = j;  r%name = ladder_name(k, j)
      r%role = merge('time    ', merge('mesh    ', 'combined', k == 0), j == 0)
      r%dt = deck%dt/2.0_dp**k
      r%nx = mesh_count(deck%nx, deck%accuracy_mesh_factor, j)
      r%ny = mesh_count(deck%ny, deck%accuracy_mesh_factor, j)
      r%grading = deck%grading**(real(deck%nx, dp)/real(r%nx, dp))
      r%h_impact = maxval(la%impact_element*first_size([r%nx, r%ny], r%grading)/ &
                          first_size([deck%nx, deck%ny], deck%grading))
      runs = [runs, r]
   end subroutine plan

   !> The size of the first of n elements graded by g over a unit length (mesh, graded_offsets).
   elemental real(dp) function first_size(n, g) result(s)
      integer, intent(in) :: n
      real(dp), intent(in) :: g                     !< ratio of successive sizes
      s = 1.0_dp/real(n, dp)
      if (g > 1.0_dp) s = (g - 1.0_dp)/(g**n - 1.0_dp)
   end function first_size

   !> Elements along one side at mesh level j: n0 factor^j rounded, at least one more a level.
   elemental integer function mesh_count(n0, factor, j) result(n)
      integer, intent(in) :: n0, j
      real(dp), intent(in) :: factor                !< &accuracy mesh_factor
      integer :: l
      n = n0
      do l = 1, j
         n = max(n + 1, nint(real(n0, dp)*factor**l))
      end do
   end function mesh_count

   !> Steps 1-3 until the target is met, the cap is reached (the candidate does not fit it, or a
   !> pass made no run after the cap turned one away) or the ladder cannot be refined.
   subroutine climb(deck, la, lad, out, stat, errmsg)
      type(deck_t), intent(in) :: deck
      type(launcher_t), intent(inout) :: la
      type(ladder_t), intent(inout) :: lad
      type(accuracy_outcome_t), intent(out) :: out
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer :: i, iq, done_before, kj(2)
      type(choice_t) :: c
      type(judged_t) :: jd
      real(dp) :: scale(nq)
      character(len=msg_len) :: line
      do
         done_before = count(lad%runs%state == state_done)
         call run_planned(lad%runs, la, stat, errmsg)
         if (stat /= 0) return
         if (stop_caught() /= 0 .and. lad%runs(1)%state /= state_done) return   ! out%chosen 0: nothing to give
         i = findloc(lad%runs%state, state_failed, dim=1)
         if (lad%runs(1)%state /= state_done) errmsg = 'accuracy: the first run did not finish within ' // &
            '&accuracy max_cpu_s = ' // real_short(la%cap) // ' s'
         associate (r => lad%runs(max(i, 1)))
         if (i > 0) errmsg = 'accuracy: the run ' // trim(r%name) // ' (dt ' // real_short(r%dt) // &
            ' s, mesh ' // int_str(r%nx) // ' x ' // int_str(r%ny) // ') failed, exit status ' // &
            int_str(r%exit_code) // ': ' // trim(r%status) // '; see ' // la%dir // trim(r%name) // '.log'
         end associate
         stat = merge(1, 0, i > 0 .or. lad%runs(1)%state /= state_done)
         if (stat /= 0) return
         where (lad%runs%state == state_done .and. lad%runs%has(1)) lad%runs%contact_radius = &   ! Hertz: sqrt(R (F/k)^(2/3))
            sqrt(0.5_dp*deck%diameter*(max(lad%runs%q(1), 0.0_dp)/deck%k)**(2.0_dp/3.0_dp))
         lad%estimated = lad%runs(1)%has
         lad%estimated(iq_failure) = lad%estimated(iq_failure) .and. strength_given(deck)
         lad%targeted = lad%targeted .and. lad%estimated
         call build_axes(lad)
         kj = final_run(lad)                        ! the best run so far: the one given when not met
         if (stop_caught() /= 0) exit
         jd = judge_run(lad, kj(1), kj(2))          ! one line of progress: its relative errors targeted
         scale = max(error_scale(jd%value), tiny(1.0_dp))
         line = 'accuracy: errors so far, at ' // ladder_name(kj(1), kj(2)) // ':'
         do iq = 1, nq
            if (lad%targeted(iq)) line = trim(line) // ' ' // trim(result_keys(iq)) // ' ' // &
               real_short(100.0_dp*jd%err(iq)/scale(iq)) // ' %'
         end do
         write (la%unit, '(a)') trim(line) // ' (target ' // real_short(100.0_dp*lad%target) // ' %)'
         flush (la%unit)
         c = choose_run(lad, la)
         i = time_partner(lad%runs, c%k, c%j)
         out%met = c%found .and. done_run(lad%runs, c%k, c%j) .and. i < 0 .and. &
                   .not. cross_needed(lad%runs, c%k, c%j)
         if (out%met) out%status = 'met'
         if (out%met) kj = [c%k, c%j]
         if (out%met) exit
         if (c%found) then                          ! within the cap: the chosen run and its partner
            call plan(lad%runs, deck, la, c%k, c%j)
            if (i >= 0) call plan(lad%runs, deck, la, i, c%j)
            if (cross_needed(lad%runs, c%k, c%j)) call plan(lad%runs, deck, la, 1, 1)
         else if (c%beyond_cap .or. (la%cap_reached .and. count(lad%runs%state == state_done) == done_before)) then
            out%status = cap_status(lad, la, c)
            exit
         else
            call refine(deck, la, lad, out%status)
            if (len_trim(out%status) > 0) exit
         end if
      end do
      out%chosen = ladder_run(lad%runs, kj(1), kj(2))
      out%jd = judge_run(lad, kj(1), kj(2))
   end subroutine climb

   !> The status at the cap: the run that would come next (the candidate beyond the cap, else the
   !> cheapest the cap turned away), its predicted cpu time and the total it would bring.
   function cap_status(lad, la, choice) result(status)
      type(ladder_t), intent(in) :: lad
      type(launcher_t), intent(in) :: la
      type(choice_t), intent(in) :: choice          !< choose_run's (beyond the cap: the candidate, its cost)
      character(len=:), allocatable :: status, what
      real(dp) :: c, cost(size(lad%runs))
      integer :: pick, partner, kj(2)
      status = ' s; the results carry the errors reached'
      kj = choice%beyond_kj
      if (choice%beyond_cap .and. kj(2) >= 0) then
         c = choice%beyond_cost
         what = ''
         if (.not. done_run(lad%runs, kj(1), kj(2))) what = level_text(kj(1))
         partner = time_partner(lad%runs, kj(1), kj(2))
         if (partner >= 0 .and. len(what) > 0) what = what // ' and '
         if (partner >= 0) what = what // level_text(partner)
         pick = lad%mx%run(kj(2) + 1)
      else
         cost = merge(predicted_run_cost(lad%runs, la), huge(1.0_dp), lad%runs%state == state_skipped)
         pick = minloc(cost, mask=cost < huge(1.0_dp), dim=1)
         if (pick == 0) status = 'cap reached: the next run would take the cpu time of all runs past ' // &
            '&accuracy max_cpu_s = ' // real_short(la%cap) // status
         if (pick == 0) return
         c = cost(pick)
         kj = [lad%runs(pick)%k, lad%runs(pick)%j]
         what = level_text(kj(1))
      end if
      status = 'cap reached: next, ' // what // ' on the mesh ' // int_str(lad%runs(pick)%nx) // ' x ' // &
               int_str(lad%runs(pick)%ny) // ', predicted at ' // real_short(c) // ' s of cpu, ' // &
               real_short(la%spent + c) // ' s in all, past &accuracy max_cpu_s = ' // real_short(la%cap) // status
   contains
      !> 't<k>_m<j> (dt ... us)': time level k on mesh kj(2).
      function level_text(k) result(text)
         integer, intent(in) :: k
         character(len=:), allocatable :: text
         text = ladder_name(k, kj(2)) // ' (dt ' // real_short(lad%runs(1)%dt/2.0_dp**k*1.0e6_dp) // ' us)'
      end function level_text
   end function cap_status

   !> The results that must meet the target: &accuracy results, 'default' (or nothing), 'all',
   !> or summary keys separated by blanks, commas or '+'.
   subroutine targeted_results(deck, targeted, stat, errmsg)
      type(deck_t), intent(in) :: deck
      logical, intent(out) :: targeted(nq)          !< which of result_keys
      integer, intent(out) :: stat                  !< 0, or 1 for an unknown key
      character(len=*), intent(inout) :: errmsg
      character(len=:), allocatable :: rest
      integer :: cut, iq
      stat = 0
      rest = deck%accuracy_results
      do cut = 1, len(rest)
         if (rest(cut:cut) == ',' .or. rest(cut:cut) == '+') rest(cut:cut) = ' '
      end do
      rest = trim(adjustl(rest))
      targeted = rest == 'all'
      if (rest == 'default' .or. len(rest) == 0) targeted = [.true., .true., .true., .false., .false., .true., .true.]
      if (any(targeted)) return
      do while (len(rest) > 0)
         cut = index(rest // ' ', ' ')
         iq = findloc(result_keys == rest(:cut - 1), .true., dim=1)
         stat = merge(1, 0, iq == 0)
         if (iq == 0) errmsg = deck%source // ': &accuracy: results: ' // rest(:cut - 1) // &
            ' is not one of default all peak_force_N max_deflection_mm contact_duration_us ' // &
            'time_of_peak_us max_strain_y_back max_failure_index damage_dissipated_J'
         if (iq == 0) return
         targeted(iq) = .true.
         rest = trim(adjustl(rest(cut:)))
      end do
   end subroutine targeted_results

   !> No run meets the target: refines the axis whose part of the finest run's error is over half
   !> the target (else the larger part); not the mesh for a time read off dt0's steps (why).
   subroutine refine(deck, la, lad, status)
      type(deck_t), intent(in) :: deck
      type(launcher_t), intent(in) :: la
      type(ladder_t), intent(inout) :: lad
      character(len=*), intent(out) :: status      !< '' when a level was planned, else 'not met: ' and why
      type(judged_t) :: jd
      logical :: time, mesh, can_time, can_mesh, next(2), step_bound(nq)
      real(dp) :: allowed(nq)
      integer :: iq
      jd = judge_run(lad, lad%tx%levels - 1, lad%mx%levels - 1)
      allowed = lad%target*error_scale(jd%value)
      time = .false.;  mesh = .false.;  step_bound = .false.
      do iq = 1, nq
         if (.not. lad%targeted(iq) .or. jd%err(iq) <= allowed(iq)) cycle
         associate (et => jd%err_time(iq), em => jd%err_mesh(iq), half => 0.5_dp*allowed(iq))
         step_bound(iq) = lad%mx%finest(iq)%floor > half
         time = time .or. et > half .or. (et <= half .and. em <= half .and. et >= em)
         mesh = mesh .or. (.not. step_bound(iq) .and. (em > half .or. (et <= half .and. em <= half .and. em > et)))
         end associate
      end do
      can_time = lad%tx%levels <= lad%k_max
      can_mesh = lad%mx%levels < max_mesh_levels .and. max_elements >= &
                 maxval(mesh_count([deck%nx, deck%ny], deck%accuracy_mesh_factor, lad%mx%levels))
      ! an axis wanted that cannot be refined gives its turn to the other
      next = [can_time, can_mesh] .and. ([time, mesh] .or. ([mesh, time] .and. .not. [can_mesh, can_time]))
      if (next(1)) call plan(lad%runs, deck, la, lad%tx%levels, 0)
      if (next(2)) call plan(lad%runs, deck, la, 0, lad%mx%levels)
      status = ''
      if (any(next)) return
      status = 'not met: dt and the mesh cannot be refined further (the ladder''s limits)'
      if (any(step_bound)) status = 'not met: ' // trim(result_keys(findloc(step_bound, .true., dim=1))) // &
         ' is read off the time steps: the meshes, all run at the deck''s dt = ' // real_short(deck%dt*1.0e6_dp) // &
         ' us, cannot show it to the target; give a smaller dt in the deck'
   end subroutine refine

   !> <prefix>_accuracy.dat (module header): a row per run, the errors of a ladder run on the
   !> axes, NaN for the rest.
   subroutine write_accuracy_table(deck, lad, out, stat, errmsg)
      type(deck_t), intent(in) :: deck
      type(ladder_t), intent(in) :: lad
      type(accuracy_outcome_t), intent(in) :: out
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer, parameter :: nfixed = 12             ! columns before the results
      character(len=32) :: names(nfixed + 4*nq)
      character(len=96) :: texts(nfixed + 4*nq)
      character(len=msg_len) :: iomsg
      character(len=16) :: order
      character(len=:), allocatable :: key, unit
      type(axis_t) :: axes(2)
      type(judged_t) :: jd
      real(dp) :: err(nq, 3), q(nq), h_rel
      integer :: u, i, iq
      names(:nfixed) = [character(len=32) :: 'run', 'role', 'time_level', 'mesh_level', 'dt_us', 'nx', 'ny', &
         'grading', 'element_size_rel', 'cpu_s', 'chosen', 'state']
      texts(:nfixed) = [character(len=96) :: 'the run: <prefix>_acc/<run>_summary.dat', &
         'time, mesh or combined (the ladder), theory or bend_twist (a model compared)', &
         'k: dt = dt0/2^k', 'j: the mesh refined j times by &accuracy mesh_factor', 'time step (us)', &
         '&mesh nx', '&mesh ny', '&mesh grading', '1/sqrt(nx ny) relative to mesh level 0', &
         'cpu time of the run (s)', '1: the run whose results the summary gives', &
         'done, failed, or skipped (it would pass &accuracy max_cpu_s)']
      do iq = 1, nq                                 ! the result, its error, the time part, the mesh part
         key = trim(result_keys(iq));  unit = ' (' // trim(result_units(iq))
         names(nfixed + iq::nq) = [character(len=32) :: key, key // '_error', key // '_error_dt', &
                                   key // '_error_mesh']
         texts(nfixed + iq::nq) = [character(len=96) :: 'the run''s ' // key // unit // '; NaN: none)', &
            'its estimated error' // unit // '; NaN: not estimated)', 'of which the time part' // unit // ')', &
            'and the mesh part' // unit // ')']
      end do
      open (newunit=u, file=deck%prefix // '_accuracy.dat', status='replace', action='write', iostat=stat, &
            iomsg=iomsg)
      if (stat /= 0) errmsg = 'cannot write ' // deck%prefix // '_accuracy.dat: ' // trim(iomsg)
      if (stat /= 0) return
      write (u, '(a)') '# impact: accuracy ladder, one row per run (target ' // real_short(lad%target) // ')'
      call echo_deck(deck, u, '# ')
      call write_column_block(u, names, texts)
      do i = 1, size(lad%runs)
         associate (r => lad%runs(i))
         err = ieee_value(err, ieee_quiet_nan)
         q = merge(r%q, err(:, 1), r%state == state_done)
         if (r%state == state_done .and. is_ladder(r) .and. r%k < lad%tx%levels .and. r%j < lad%mx%levels) then
            jd = judge_run(lad, r%k, r%j)
            err = merge(reshape([jd%err, jd%err_time, jd%err_mesh], [nq, 3]), err, spread(lad%estimated, 2, 3))
         end if
         h_rel = sqrt(real(lad%runs(1)%nx, dp)*real(lad%runs(1)%ny, dp)/(real(r%nx, dp)*real(r%ny, dp)))
         write (u, '(a,1x,a,2(1x,i3),es15.6e3,2(1x,i5),f9.5,f9.5,es12.4,1x,i1,1x,a,*(es16.7e3))') trim(r%name), &
            trim(r%role), r%k, r%j, r%dt*1.0e6_dp, r%nx, r%ny, r%grading, h_rel, r%cpu_s, merge(1, 0, i == out%chosen), &
            state_words(r%state), q, err
         end associate
      end do
      write (u, '(a)') '# estimates of the finest level of each axis (src/accuracy/accuracy_ladder.f90):'
      write (u, '(a)') '# result axis levels observed_order asymptotic error(result''s unit) rule'
      axes = [lad%tx, lad%mx]
      do iq = 1, nq
         if (.not. lad%estimated(iq)) cycle
         do i = 1, 2
            associate (e => axes(i)%finest(iq))
            order = '-'
            if (e%order >= 0.0_dp) write (order, '(f6.2)') e%order
            write (u, '(a,1x,a,1x,i0,1x,a,1x,a,es12.4,1x,a)') '# ' // trim(result_keys(iq)), &
               merge('time', 'mesh', i == 1), axes(i)%levels, trim(adjustl(order)), &
               trim(merge('yes', 'no ', e%asymptotic)), e%error, trim(e%how)
            end associate
         end do
      end do
      close (u, iostat=stat, iomsg=iomsg)
      if (stat /= 0) errmsg = deck%prefix // '_accuracy.dat: ' // trim(iomsg)
   end subroutine write_accuracy_table

   !> <prefix>_summary.dat, then the terminal's lines (module header).
   subroutine report(deck, la, lad, out, unit, stat, errmsg)
      type(deck_t), intent(in) :: deck
      type(launcher_t), intent(in) :: la
      type(ladder_t), intent(in) :: lad
      type(accuracy_outcome_t), intent(in) :: out
      integer, intent(in) :: unit                   !< standard output
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      !> Whose the time error is of a run chosen without it measured on its mesh, and why.
      character(len=*), parameter :: unmeasured_time = &
         'mesh 0''s (the cap left no neighbouring time level on the chosen mesh)'
      character(len=*), parameter :: two_meshes = 'two levels: 3 times their difference (Roache''s factor of safety 3)'
      type(summary_t) :: s
      type(summary_item_t), allocatable :: items(:)
      character(len=msg_len) :: line
      character(len=msg_len), allocatable :: lines(:)   ! the results' and the models' terminal lines
      character(len=:), allocatable :: key, unit_name
      real(dp) :: rel(nq), in_chosen
      integer :: i, iq
      associate (r => lad%runs(out%chosen), jd => out%jd)
      rel = relative(jd%err, error_scale(jd%value))
      in_chosen = la%spent/max(r%cpu_s, tiny(1.0_dp))   ! the cpu time in runs of the chosen
      call read_summary(la%dir // trim(r%name) // '_summary.dat', s, stat, errmsg)
      if (stat /= 0) return
      allocate (items(0), lines(0))
      do i = 1, size(s%keys)
         call summary_text(items, trim(s%keys(i)), trim(s%texts(i)))
      end do
      call put('accuracy_target', '-', lad%target)
      call summary_text(items, 'accuracy_status', trim(out%status))
      if (out%stop_signal > 0) call summary_integer(items, 'accuracy_stop_signal', out%stop_signal)
      call summary_text(items, 'accuracy_values', 'of the run chosen, not extrapolated')
      key = 'true'
      if (.not. jd%time_measured) key = 'false: ' // unmeasured_time
      call summary_text(items, 'time_error_measured', key)
      if (jd%two_levels) call summary_text(items, 'time_error_estimate', &
                                           'two levels: Roache''s grid convergence index, Fs = 3')
      if (lad%mx%levels == 2) call summary_text(items, 'mesh_error_estimate', two_meshes)
      call summary_text(items, 'chosen_run', la%dir // trim(r%name))
      call summary_real(items, 'chosen_dt_us', 'chosen_dt', 's', r%dt, 1.0e6_dp)
      call summary_integer(items, 'chosen_nx', r%nx)
      call summary_integer(items, 'chosen_ny', r%ny)
      call put('chosen_grading', '-', r%grading)
      call summary_text(items, 'chosen_theory', trim(la%theory))
      do iq = 1, nq
         if (.not. lad%estimated(iq)) cycle
         key = trim(result_keys(iq));  unit_name = trim(result_units(iq))
         call put(key // '_error', unit_name, jd%err(iq))
         call put(key // '_error_dt', unit_name, jd%err_time(iq))
         call put(key // '_error_mesh', unit_name, jd%err_mesh(iq))
         if (iq == iq_peak_time) call put(key // '_error_maxima', unit_name, jd%err_maxima(iq))
         call put(key // '_relative_error', '-', rel(iq))
         write (line, '(a,es14.6,a,es10.3,a,f7.3,a,es10.3,a,es10.3,a)') result_keys(iq), jd%value(iq), ' +- ', &
            jd%err(iq), ' (', 100.0_dp*rel(iq), ' %; dt ', jd%err_time(iq), ', mesh ', jd%err_mesh(iq), ')'
         lines = [lines, '  ' // line(:msg_len - 2)]
      end do
      do i = 1, size(out%cmp)
         call comparison_report(items, lines, out%cmp(i), lad, out%chosen)
      end do
      call summary_integer(items, 'accuracy_runs', count(lad%runs%state == state_done))
      call summary_real(items, 'accuracy_cpu_s', 'accuracy_cpu', 's', la%spent, 1.0_dp)
      call put('accuracy_cpu_in_chosen_runs', '-', in_chosen)
      call summary_real(items, 'accuracy_wall_s', 'accuracy_wall', 's', out%wall_s, 1.0_dp)
      call write_summary_file(deck, items, stat, errmsg)
      if (stat /= 0) return
      write (unit, '(a)') 'accuracy: ' // trim(out%status)
      if (jd%two_levels) write (unit, '(a)') 'accuracy: the time error on the chosen mesh is from two ' // &
         'time levels: Roache''s grid convergence index, factor of safety 3'
      if (lad%mx%levels == 2) write (unit, '(a)') 'accuracy: the mesh error is from ' // two_meshes
      if (.not. jd%time_measured) write (unit, '(a)') 'accuracy: the time error was not measured on ' // &
         'the chosen mesh: it is ' // unmeasured_time
      if (jd%err_maxima(iq_peak_time) > 0.0_dp) write (unit, '(a)') 'accuracy: ' // &
         trim(result_keys(iq_peak_time)) // ': the force has other maxima within the peak force''s error of it, ' // &
         'up to ' // real_short(jd%err_maxima(iq_peak_time)) // ' us from the peak: which is the highest ' // &
         'is not settled at these settings (its error counts them)'
      write (unit, '(a)') 'accuracy: results of run ' // trim(r%name) // ' (dt ' // real_short(r%dt*1.0e6_dp) // &
         ' us, mesh ' // int_str(r%nx) // ' x ' // int_str(r%ny) // ', grading ' // real_short(r%grading) // &
         ', ' // trim(la%theory) // '), not extrapolated; error = time part + mesh part + their interaction'
      write (unit, '(a)') (trim(lines(i)), i = 1, size(lines))
      write (unit, '(a)') 'accuracy: ' // int_str(count(lad%runs%state == state_done)) // ' runs, cpu ' // &
         real_short(la%spent) // ' s (' // real_short(in_chosen) // ' times the run chosen), wall ' // &
         real_short(out%wall_s) // ' s on ' // int_str(la%cpus) // ' CPUs; every run: ' // la%dir // &
         '; summary: ' // la%dir(:len(la%dir) - 5) // '_summary.dat'
      end associate
   contains
      !> A real item whose key is its name, in the result's unit.
      subroutine put(name, unit_name, value)
         character(len=*), intent(in) :: name, unit_name
         real(dp), intent(in) :: value
         call summary_real(items, name, name, unit_name, value, 1.0_dp)
      end subroutine put
   end subroutine report

end module accuracy_driver
