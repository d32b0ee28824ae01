!> Which model a scene needs (step 4 of accuracy_driver): one run with the other theory
!> (linear against von Karman) and, when the laminate has D16, D26, one with the other
!> bend-twist model (the paper's averaged plate against the full plate that keeps them); their
!> relative changes give the verdict (accuracy_report, model_needed). First on the chosen mesh
!> at dt0, 2^k times cheaper; again at the chosen settings only when the change, within its
!> band (change_band), could turn the verdict. Past the cap: at the costliest ladder run whose
!> variant fits.
module model_comparison
   use kinds, only: dp, msg_len
   use deck_schema, only: deck_t
   use number_text, only: real_short
   use materials, only: laminate_t
   use scene_model, only: scene_t, model_laminate, choose_domain, coupling_tol
   use accuracy_runs, only: run_t, launcher_t, nq, result_keys, run_planned, state_planned, state_done, &
      predicted_run_cost, is_ladder
   use accuracy_ladder, only: axis_t, judged_t, judge_run, ladder_run
   use accuracy_report, only: comparison_t, accuracy_outcome_t, model_changes, model_required
   implicit none
   private
   public :: compare_models, comparison_base, variant_bases, bend_twist_variant, coarse_base, verdict_settled

contains

   !> Step 4 (module header): the comparisons first at coarse_base, kept where their verdict is
   !> settled (verdict_settled) or the chosen settings pass the cap, else made again there
   !> (variant_bases). The report names the run compared with.
   subroutine compare_models(deck, la, runs, tx, mx, out, stat, errmsg)
      type(deck_t), intent(in) :: deck              !< the deck
      type(launcher_t), intent(inout) :: la         !< the launcher
      type(run_t), allocatable, intent(inout) :: runs(:)   !< the runs
      type(axis_t), intent(in) :: tx, mx            !< the time and mesh axes
      type(accuracy_outcome_t), intent(inout) :: out   !< the outcome (the run chosen); its comparisons out
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< what failed
      character(len=*), parameter :: past_cap = 'a run at its settings would pass &accuracy max_cpu_s'
      type(comparison_t) :: first(2), second(2)
      real(dp) :: slack(nq)
      integer :: coarse, i, base(2)
      logical :: again(2)
      associate (cmp => out%cmp)
      again = .true.                                ! made (again) at the chosen settings
      slack = 0.0_dp
      coarse = coarse_base(runs, out%chosen)
      if (coarse /= out%chosen) then
         slack = change_slack(runs, tx, mx, out, coarse)
         call make_variants(deck, la, runs, variant_bases(deck, la%scene, runs, la, coarse, again), again, first, &
                            stat, errmsg)
         if (stat /= 0) return
         cmp = first
         do i = 1, 2
            if (first(i)%base /= coarse) then      ! even that run would pass the cap
               cmp(i)%at = past_cap
               again(i) = .false.
            else if (verdict_settled(first(i), runs, out, slack)) then
               again(i) = .false.
               cmp(i)%at = coarse_words(.true., change_band(model_changes(first(i), runs, out), slack), out)
            end if
         end do
         base = variant_bases(deck, la%scene, runs, la, out%chosen, again)
         do i = 1, 2
            if (.not. again(i) .or. base(i) == out%chosen) cycle
            again(i) = .false.                      ! the chosen settings would pass the cap
            if (made(first(i))) &
               cmp(i)%at = coarse_words(.false., change_band(model_changes(first(i), runs, out), slack), out)
         end do
         if (.not. any(again)) return
      end if
      call make_variants(deck, la, runs, variant_bases(deck, la%scene, runs, la, out%chosen, again), again, second, &
                         stat, errmsg)
      if (stat /= 0) return
      do i = 1, 2
         if (.not. again(i)) cycle
         if (second(i)%run == 0 .or. coarse == out%chosen .or. .not. made(cmp(i))) then
            cmp(i) = second(i)
            if (cmp(i)%base /= out%chosen) cmp(i)%at = past_cap
         else if (made(second(i))) then
            cmp(i) = second(i)
         else                                       ! the cap skipped the second: the first stands
            cmp(i)%at = coarse_words(.false., change_band(model_changes(cmp(i), runs, out), slack), out)
         end if
      end do
      end associate
   contains
      !> The comparison's variant was made and has results.
      logical function made(c)
         type(comparison_t), intent(in) :: c
         made = .false.
         if (c%run > 0) made = runs(c%run)%state == state_done
      end function made
   end subroutine compare_models

   !> The variants wanted (theory, bend-twist), each at the settings of its run base(i), run.
   subroutine make_variants(deck, la, runs, base, want, cmp, stat, errmsg)
      type(deck_t), intent(in) :: deck              !< the deck
      type(launcher_t), intent(inout) :: la         !< the launcher
      type(run_t), allocatable, intent(inout) :: runs(:)   !< the runs
      integer, intent(in) :: base(2)                !< the runs compared with: the theory's, the bend-twist's
      logical, intent(in) :: want(2)                !< the theory, the bend-twist model
      type(comparison_t), intent(out) :: cmp(2)     !< the two comparisons (run 0 where not wanted)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< what failed
      type(run_t) :: r
      character(len=16) :: other
      cmp%base = base
      cmp(1)%what = 'theory'
      cmp(1)%richer = 'nonlinear';  cmp(1)%simpler = 'linear'
      cmp(1)%chosen_richer = la%theory /= 'linear'
      other = merge(cmp(1)%simpler, cmp(1)%richer, cmp(1)%chosen_richer)
      cmp(1)%compared = trim(other) // ' instead of ' // trim(la%theory)
      if (want(1)) then
         r = planned_copy(runs(base(1)))
         r%role = 'theory'
         r%name = trim(runs(base(1))%name) // '_' // trim(other)
         r%variant(1) = "analysis.theory='" // trim(other) // "'"
         runs = [runs, r]
         cmp(1)%run = size(runs)
      end if
      cmp(2)%what = 'bend_twist'
      r = planned_copy(runs(base(2)))
      call bend_twist_variant(deck, la%scene, runs(base(2)), r, cmp(2))
      if (want(2) .and. len_trim(cmp(2)%note) == 0) then
         runs = [runs, r]
         cmp(2)%run = size(runs)
      end if
      call run_planned(runs, la, stat, errmsg)
   end subroutine make_variants

   !> A run at the settings of run c, planned.
   pure function planned_copy(c) result(r)
      type(run_t), intent(in) :: c                  !< the run
      type(run_t) :: r
      r = c
      r%state = state_planned;  r%cpu_s = 0.0_dp;  r%has = .false.;  r%variant = '';  r%status = ''
      r%exit_code = 0;  r%pid = -1
   end function planned_copy

   !> The runs the two comparisons are made at: x, or where a variant does not fit the cap the
   !> costliest ladder run done whose variant does (comparison_base), the bend-twist's beside
   !> the theory's, each priced as it would run.
   function variant_bases(deck, scene, runs, la, x, want) result(base)
      type(deck_t), intent(in) :: deck              !< the deck
      type(scene_t), intent(in) :: scene            !< the scene of the deck's model
      type(run_t), intent(in) :: runs(:)            !< the runs
      type(launcher_t), intent(in) :: la            !< the launcher (its cost model and spending)
      integer, intent(in) :: x                      !< the run preferred
      logical, intent(in) :: want(2)                !< the theory, the bend-twist model
      integer :: base(2)
      real(dp) :: cost_theory(size(runs)), cost_bt(size(runs)), reserve
      type(run_t) :: r
      type(comparison_t) :: c
      integer :: i
      do i = 1, size(runs)
         cost_theory(i) = predicted_run_cost(runs(i), la)
         r = planned_copy(runs(i))
         call bend_twist_variant(deck, scene, runs(i), r, c)
         cost_bt(i) = merge(predicted_run_cost(r, la), 0.0_dp, len_trim(c%note) == 0)   ! a note: no run
      end do
      base = x
      reserve = 0.0_dp
      if (want(1)) then
         base(1) = comparison_base(runs, la, x, cost_theory)
         if (la%spent + cost_theory(base(1)) <= la%cap) reserve = cost_theory(base(1))
      end if
      if (want(2)) base(2) = comparison_base(runs, la, x, cost_bt + reserve)
   end function variant_bases

   !> The run on the chosen run's mesh at dt0, or the chosen one when that is not done.
   integer function coarse_base(runs, chosen) result(coarse)
      type(run_t), intent(in) :: runs(:)            !< the runs
      integer, intent(in) :: chosen                 !< the run chosen
      coarse = ladder_run(runs, 0, runs(chosen)%j)
      if (coarse == 0) then
         coarse = chosen
      else if (runs(coarse)%state /= state_done) then
         coarse = chosen
      end if
   end function coarse_base

   !> How far a model's change at run coarse may lie from that at the chosen settings:
   !> 2 (e_t(coarse) + e_t(chosen)) / |q|, the variant's time error taken as the base's.
   function change_slack(runs, tx, mx, out, coarse) result(slack)
      type(run_t), intent(in) :: runs(:)            !< the runs
      type(axis_t), intent(in) :: tx, mx            !< the time and mesh axes
      type(accuracy_outcome_t), intent(in) :: out   !< the outcome (the run chosen, its errors)
      integer, intent(in) :: coarse                 !< the run compared with first
      real(dp) :: slack(nq)
      type(judged_t) :: jd
      jd = judge_run(runs, tx, mx, 0, runs(coarse)%j, out%target, out%estimated)
      where (runs(coarse)%q /= 0.0_dp)
         slack = 2.0_dp*(jd%err_time + out%jd%err_time)/abs(runs(coarse)%q)
      elsewhere
         slack = huge(1.0_dp)
      end where
   end function change_slack

   !> The band about a model's changes within which the change at the chosen step lies: slack,
   !> and change_share of the change for the variant's own time error (docs/PERFORMANCE.md).
   pure function change_band(change, slack) result(band)
      real(dp), intent(in) :: change(nq)            !< the relative changes (model_changes)
      real(dp), intent(in) :: slack(nq)             !< change_slack
      real(dp) :: band(nq)
      real(dp), parameter :: change_share = 0.1_dp   ! share of the change (-)
      band = slack + change_share*abs(change)
   end function change_band

   !> Whether the verdict of c (model_required) is the same for every change within its band;
   !> a comparison not made settles nothing.
   logical function verdict_settled(c, runs, out, slack) result(settled)
      type(comparison_t), intent(in) :: c           !< the comparison
      type(run_t), intent(in) :: runs(:)            !< the runs
      type(accuracy_outcome_t), intent(in) :: out   !< the outcome (the target, the results targeted)
      real(dp), intent(in) :: slack(nq)             !< change_slack
      real(dp) :: change(nq), band(nq)
      settled = .false.
      if (c%run == 0) return
      if (runs(c%run)%state /= state_done) return
      change = model_changes(c, runs, out)
      band = change_band(change, slack)
      settled = model_required(max(abs(change) - band, 0.0_dp), out) .or. &
                .not. model_required(abs(change) + band, out)
   end function verdict_settled

   !> Why a comparison stays at the chosen mesh's run at dt0, with the bands targeted.
   function coarse_words(settled, band, out) result(text)
      logical, intent(in) :: settled                !< verdict_settled
      real(dp), intent(in) :: band(nq)              !< change_band
      type(accuracy_outcome_t), intent(in) :: out   !< the outcome (the results targeted)
      character(len=:), allocatable :: text, bands
      integer :: iq
      bands = ''
      do iq = 1, nq
         if (.not. out%targeted(iq)) cycle
         if (len(bands) > 0) bands = bands // ', '
         bands = bands // trim(result_keys(iq)) // ' ' // real_short(100.0_dp*min(band(iq), 1.0_dp)) // ' %'
      end do
      text = 'the chosen mesh at the ladder''s first step; the change at the chosen step lies within ' // bands // &
             ' of it (twice the time errors of both steps and a tenth of the change)'
      if (settled) then
         text = text // ', which leaves the verdict as it is'
      else
         text = text // ', which could turn the verdict; a run at the chosen settings would pass &accuracy max_cpu_s'
      end if
   end function coarse_words

   !> The run a model is compared at: the chosen one, else the costliest ladder run done whose
   !> variant, predicted to cost cost(i), fits the cap (the chosen one when none does).
   integer function comparison_base(runs, la, chosen, cost) result(base)
      type(run_t), intent(in) :: runs(:)            !< the runs
      type(launcher_t), intent(in) :: la            !< the launcher (its spending and cap)
      integer, intent(in) :: chosen                 !< the run chosen
      real(dp), intent(in) :: cost(:)               !< the variant's predicted cost at each run's settings (s)
      integer :: i
      base = chosen
      if (fits(chosen)) return
      do i = 1, size(runs)
         if (runs(i)%state /= state_done .or. .not. is_ladder(runs(i)) .or. .not. fits(i)) cycle
         if (base == chosen) then
            base = i
         else if (cost(i) > cost(base)) then
            base = i
         end if
      end do
   contains
      !> A run at the settings of run i stays within the cap.
      pure logical function fits(i)
         integer, intent(in) :: i
         fits = la%c_base < 0.0_dp .or. la%spent + cost(i) <= la%cap
      end function fits
   end function comparison_base

   !> The run of the other bend-twist model at the settings of run c, or a note why there is none.
   subroutine bend_twist_variant(deck, scene, c, r, cmp)
      type(deck_t), intent(in) :: deck              !< the deck
      type(scene_t), intent(in) :: scene            !< the scene of the deck's model
      type(run_t), intent(in) :: c                  !< the run chosen
      type(run_t), intent(inout) :: r               !< the variant (c's settings in)
      type(comparison_t), intent(inout) :: cmp      !< what it compares, or the note
      real(dp) :: quarters
      integer :: fx, fy
      r%role = 'bend_twist';  r%variant = ''
      cmp%richer = 'keep';  cmp%simpler = 'drop'           ! &laminate bend_twist
      cmp%chosen_richer = .not. scene%averaged
      if (all(scene%couplings(1:2) <= coupling_tol)) then
         cmp%note = 'the laminate has D16 = D26 = 0'
         return
      end if
      if (scene%domain == 'strip') then
         cmp%note = 'a strip (cylindrical bending) has no full plate to compare with'
         return
      end if
      quarters = merge(1.0_dp, merge(2.0_dp, 4.0_dp, scene%domain == 'half'), scene%domain == 'quarter')
      if (scene%averaged) then
         ! the full plate that keeps D16, D26: its counts, those of the domain mirrored
         fx = 2;  fy = 2
         if (deck%domain /= 'auto' .and. scene%domain == 'half') then
            fx = merge(1, 2, deck%y0 == 0.0_dp);  fy = merge(2, 1, deck%y0 == 0.0_dp)
         end if
         if (deck%domain == 'full') then
            fx = 1;  fy = 1
         end if
         r%nx = c%nx*fx;  r%ny = c%ny*fy
         r%variant(1) = "mesh.domain='full'"
         r%variant(2) = 'mesh.average_bend_twist=.false.'
         r%variant(3) = "laminate.bend_twist='keep'"
         ! a ladder run's counts the quarter's, doubled across the centre lines of an 'auto' domain
         r%cost_factor = merge(1.0_dp/quarters, 1.0_dp, deck%domain == 'auto')
         r%name = trim(c%name) // '_bend_twist_keep'
         cmp%compared = 'the full plate with D16, D26 kept instead of D16 = D26 = 0 (' // trim(scene%domain) // ')'
      else
         ! the paper's averaging: D16 = D26 = 0, on the smallest domain that allows
         r%variant(1) = "laminate.bend_twist='drop'"
         r%cost_factor = reduced_quarters(deck)/quarters
         r%name = trim(c%name) // '_bend_twist_drop'
         cmp%compared = 'D16 = D26 = 0 (the paper''s averaging, section 3.1) instead of D16, D26 kept'
      end if
   end subroutine bend_twist_variant

   !> The quarters of the domain 'auto' picks once D16 and D26 are dropped (1, 2 or 4).
   real(dp) function reduced_quarters(deck) result(quarters)
      type(deck_t), intent(in) :: deck              !< the deck
      type(deck_t) :: d
      type(scene_t) :: s
      type(laminate_t) :: lmt
      integer :: stat
      character(len=msg_len) :: errmsg
      d = deck
      d%bend_twist = 'drop'
      call model_laminate(d, lmt, s)
      call choose_domain(d, s, stat, errmsg)
      quarters = 4.0_dp
      if (stat /= 0) return
      if (s%domain == 'quarter') quarters = 1.0_dp
      if (s%domain == 'half') quarters = 2.0_dp
   end function reduced_quarters

end module model_comparison
