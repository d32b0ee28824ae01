!> Which model a scene needs (docs/ACCURACY.md): one run with the other theory (linear against
!> von Karman) and, when the laminate has D16, D26, one with the other bend-twist model (the
!> paper's averaged plate, section 3.1, against the full plate that keeps them); their relative
!> changes give the verdict (model_needed). First on the chosen mesh at dt0, 2^k times cheaper;
!> again at the chosen settings only when the change, within its band (verdict_settled), could
!> turn the verdict. Past the cap: at the costliest ladder run whose variant fits.
module model_comparison
   use kinds, only: dp, msg_len
   use deck_schema, only: deck_t
   use number_text, only: real_short
   use materials, only: laminate_t
   use scene_model, only: scene_t, model_laminate, choose_domain, coupling_tol
   use result_files, only: summary_item_t, summary_real, summary_text
   use accuracy_runs, only: run_t, launcher_t, nq, result_keys, run_planned, state_planned, state_done, &
      state_skipped, state_stopped, predicted_run_cost, is_ladder, error_scale
   use accuracy_ladder, only: ladder_t, judged_t, judge_run, ladder_run
   implicit none
   private
   public :: comparison_t, compare_models, comparison_base, variant_bases, bend_twist_variant, coarse_base, &
             verdict_settled, model_needed, comparison_report, relative

   !> A model compared: the theory, or D16, D26.
   type :: comparison_t
      character(len=12) :: what = ''               !< 'theory' or 'bend_twist'
      character(len=160) :: compared = ''          !< what the other run changes
      integer :: run = 0                           !< its run, 0 when none was made
      integer :: base = 0                          !< the run it is compared with (the chosen, or another: at)
      character(len=400) :: at = ''                !< why base is not the run chosen
      character(len=160) :: note = ''              !< why none was made
      character(len=16) :: richer = ''             !< the fuller model: 'nonlinear', or 'keep' (D16, D26)
      character(len=16) :: simpler = ''            !< the other: 'linear', or 'drop' (D16 = D26 = 0)
      logical :: chosen_richer = .true.            !< the run chosen has the fuller model
   end type comparison_t

   !> Why a comparison is not at the run chosen.
   character(len=*), parameter :: past_cap = 'a run at its settings would pass &accuracy max_cpu_s'

contains

   !> The comparisons (module header): first at coarse_base, kept where their verdict is settled
   !> (verdict_settled) or the chosen settings pass the cap, else made again there.
   subroutine compare_models(deck, la, lad, chosen, cmp, stat, errmsg)
      type(deck_t), intent(in) :: deck
      type(launcher_t), intent(inout) :: la
      type(ladder_t), intent(inout) :: lad          !< the variants added to its runs
      integer, intent(in) :: chosen
      type(comparison_t), intent(out) :: cmp(2)     !< the theory's, the bend-twist model's
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      type(comparison_t) :: second(2)
      type(judged_t) :: jd, jc
      real(dp) :: slack(nq)
      integer :: coarse, i, base(2)
      logical :: again(2), settled
      again = .true.;  slack = 0.0_dp               ! again: made (again) at the chosen settings
      coarse = coarse_base(lad%runs, chosen)
      if (coarse /= chosen) then
         ! how far the change at coarse may lie from that at the chosen settings: 2 (e_t(coarse) +
         ! e_t(chosen)) / |q|, the variant's time error taken as the base's
         jd = judge_run(lad, 0, lad%runs(coarse)%j)
         jc = judge_run(lad, lad%runs(chosen)%k, lad%runs(chosen)%j)
         slack = huge(1.0_dp)
         where (lad%runs(coarse)%q /= 0.0_dp) slack = 2.0_dp*(jd%err_time + jc%err_time)/abs(lad%runs(coarse)%q)
         call make_variants(deck, la, lad%runs, variant_bases(deck, lad%runs, la, coarse, again), again, cmp, &
                            stat, errmsg)
         if (stat /= 0) return
         do i = 1, 2
            settled = verdict_settled(cmp(i), lad, slack)
            again(i) = cmp(i)%base == coarse .and. .not. settled
            if (cmp(i)%base /= coarse) cmp(i)%at = past_cap   ! even that run would pass the cap
            if (cmp(i)%base == coarse .and. made(cmp(i), lad%runs)) cmp(i)%at = coarse_words(settled, cmp(i))
         end do
         base = variant_bases(deck, lad%runs, la, chosen, again)
         where (base /= chosen) again = .false.     ! the chosen settings would pass the cap
         if (.not. any(again)) return
      end if
      call make_variants(deck, la, lad%runs, variant_bases(deck, lad%runs, la, chosen, again), again, second, &
                         stat, errmsg)
      if (stat /= 0) return
      do i = 1, 2                                   ! the cap skipped the second after a first: it stands
         if (.not. again(i) .or. (made(cmp(i), lad%runs) .and. second(i)%run > 0 .and. &
             .not. made(second(i), lad%runs))) cycle
         cmp(i) = second(i)
         if (cmp(i)%base /= chosen) cmp(i)%at = past_cap
      end do
   contains
      !> Why a comparison stays at the chosen mesh's run at dt0, with the bands targeted.
      function coarse_words(settled, c) result(text)
         logical, intent(in) :: settled            !< verdict_settled
         type(comparison_t), intent(in) :: c
         character(len=:), allocatable :: text
         real(dp) :: band(nq)
         integer :: iq
         band = slack + 0.1_dp*abs(model_changes(c, lad))   ! a tenth: the variant's own time error
         text = 'the chosen mesh at the ladder''s first step; the change at the chosen step lies within'
         do iq = 1, nq
            if (.not. lad%targeted(iq)) cycle
            if (text(len(text):) == '%') text = text // ','
            text = text // ' ' // trim(result_keys(iq)) // ' ' // real_short(100.0_dp*min(band(iq), 1.0_dp)) // ' %'
         end do
         text = text // ' of it (twice the time errors of both steps and a tenth of the change), which '
         if (settled) text = text // 'leaves the verdict as it is'
         if (.not. settled) text = text // 'could turn the verdict; a run at the chosen settings would pass ' // &
            '&accuracy max_cpu_s'
      end function coarse_words
   end subroutine compare_models

   !> The variants wanted (theory, bend-twist), each at the settings of its run base(i), run.
   subroutine make_variants(deck, la, runs, base, want, cmp, stat, errmsg)
      type(deck_t), intent(in) :: deck
      type(launcher_t), intent(inout) :: la
      type(run_t), allocatable, intent(inout) :: runs(:)
      integer, intent(in) :: base(2)                !< the runs compared with: the theory's, the bend-twist's
      logical, intent(in) :: want(2)                !< the theory, the bend-twist model
      type(comparison_t), intent(out) :: cmp(2)     !< run 0 where not wanted
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      type(run_t) :: r
      character(len=16) :: other
      cmp%base = base
      cmp(1)%what = 'theory';  cmp(1)%richer = 'nonlinear';  cmp(1)%simpler = 'linear'
      cmp(1)%chosen_richer = la%theory /= 'linear'
      other = merge(cmp(1)%simpler, cmp(1)%richer, cmp(1)%chosen_richer)
      cmp(1)%compared = trim(other) // ' instead of ' // trim(la%theory)
      if (want(1)) then
         r = planned_copy(runs(base(1)))
         r%role = 'theory';  r%name = trim(runs(base(1))%name) // '_' // trim(other)
         r%variant(1) = "analysis.theory='" // trim(other) // "'"
         runs = [runs, r];  cmp(1)%run = size(runs)
      end if
      cmp(2)%what = 'bend_twist'
      r = planned_copy(runs(base(2)))
      call bend_twist_variant(deck, la%scene, runs(base(2)), r, cmp(2))
      if (want(2) .and. len_trim(cmp(2)%note) == 0) runs = [runs, r]
      if (want(2) .and. len_trim(cmp(2)%note) == 0) cmp(2)%run = size(runs)
      call run_planned(runs, la, stat, errmsg)
   end subroutine make_variants

   !> A run at the settings of run c, planned.
   pure function planned_copy(c) result(r)
      type(run_t), intent(in) :: c
      type(run_t) :: r
      r = c
      r%state = state_planned;  r%cpu_s = 0.0_dp;  r%has = .false.;  r%variant = '';  r%status = ''
      r%exit_code = 0;  r%pid = -1
   end function planned_copy

   !> The runs the two comparisons are made at: x, or where a variant does not fit the cap
   !> comparison_base's, the bend-twist's beside the theory's, each priced as it would run.
   function variant_bases(deck, runs, la, x, want) result(base)
      type(deck_t), intent(in) :: deck
      type(run_t), intent(in) :: runs(:)
      type(launcher_t), intent(in) :: la
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
         call bend_twist_variant(deck, la%scene, runs(i), r, c)
         cost_bt(i) = merge(predicted_run_cost(r, la), 0.0_dp, len_trim(c%note) == 0)   ! a note: no run
      end do
      base = x;  reserve = 0.0_dp
      if (want(1)) then
         base(1) = comparison_base(runs, la, x, cost_theory)
         if (la%spent + cost_theory(base(1)) <= la%cap) reserve = cost_theory(base(1))
      end if
      if (want(2)) base(2) = comparison_base(runs, la, x, cost_bt + reserve)
   end function variant_bases

   !> The run on the chosen run's mesh at dt0, or the chosen one when that is not done.
   pure integer function coarse_base(runs, chosen) result(coarse)
      type(run_t), intent(in) :: runs(:)
      integer, intent(in) :: chosen
      coarse = ladder_run(runs, 0, runs(chosen)%j)
      if (coarse == 0) coarse = chosen
      if (runs(coarse)%state /= state_done) coarse = chosen
   end function coarse_base

   !> Whether the verdict of c (model_needed) is the same for every change within its band;
   !> a comparison not made settles nothing.
   logical function verdict_settled(c, lad, slack) result(settled)
      type(comparison_t), intent(in) :: c
      type(ladder_t), intent(in) :: lad
      real(dp), intent(in) :: slack(nq)             !< how far the change may be from the chosen's
      real(dp) :: change(nq), band(nq)
      settled = .false.
      if (.not. made(c, lad%runs)) return
      change = model_changes(c, lad);  band = slack + 0.1_dp*abs(change)
      settled = model_needed(c, max(abs(change) - band, 0.0_dp), lad) == model_needed(c, abs(change) + band, lad)
   end function verdict_settled

   !> Whether comparison c has its run done.
   pure logical function made(c, runs)
      type(comparison_t), intent(in) :: c
      type(run_t), intent(in) :: runs(:)
      made = c%run > 0 .and. any(runs(max(c%run, 1):c%run)%state == state_done)
   end function made

   !> The run a model is compared at: the chosen one, else the costliest ladder run done whose
   !> variant, predicted to cost cost(i), fits the cap (the chosen one when none does).
   integer function comparison_base(runs, la, chosen, cost) result(base)
      type(run_t), intent(in) :: runs(:)
      type(launcher_t), intent(in) :: la
      integer, intent(in) :: chosen
      real(dp), intent(in) :: cost(:)               !< the variant's predicted cost at each run's settings (s)
      logical :: fits(size(cost))
      fits = la%c_base < 0.0_dp .or. la%spent + cost <= la%cap
      base = maxloc(cost, mask=runs%state == state_done .and. is_ladder(runs) .and. fits, dim=1)
      if (fits(chosen) .or. base == 0) base = chosen
   end function comparison_base

   !> The run of the other bend-twist model at the settings of run c, or a note why there is none.
   subroutine bend_twist_variant(deck, scene, c, r, cmp)
      type(deck_t), intent(in) :: deck
      type(scene_t), intent(in) :: scene            !< the scene of the deck's model
      type(run_t), intent(in) :: c
      type(run_t), intent(inout) :: r               !< the variant (c's settings in)
      type(comparison_t), intent(inout) :: cmp      !< what it compares, or the note
      real(dp) :: quarters
      integer :: f(2), stat
      type(deck_t) :: d
      type(scene_t) :: s
      type(laminate_t) :: lmt
      character(len=msg_len) :: errmsg
      r%role = 'bend_twist';  r%variant = ''
      cmp%richer = 'keep';  cmp%simpler = 'drop'           ! &laminate bend_twist
      cmp%chosen_richer = .not. scene%averaged
      if (scene%domain == 'strip') cmp%note = 'a strip (cylindrical bending) has no full plate to ' // &
         'compare with'
      if (all(scene%couplings(1:2) <= coupling_tol)) cmp%note = 'the laminate has D16 = D26 = 0'
      if (len_trim(cmp%note) > 0) return
      quarters = merge(1.0_dp, merge(2.0_dp, 4.0_dp, scene%domain == 'half'), scene%domain == 'quarter')
      if (scene%averaged) then
         ! the full plate that keeps D16, D26: its counts, those of the domain mirrored
         f = 2
         if (deck%domain /= 'auto' .and. scene%domain == 'half') f = merge([1, 2], [2, 1], deck%y0 == 0.0_dp)
         if (deck%domain == 'full') f = 1
         r%nx = c%nx*f(1);  r%ny = c%ny*f(2)
         r%variant(1:3) = [character(len=64) :: "mesh.domain='full'", 'mesh.average_bend_twist=.false.', &
                           "laminate.bend_twist='keep'"]
         ! a ladder run's counts the quarter's, doubled across the centre lines of an 'auto' domain
         r%cost_factor = merge(1.0_dp/quarters, 1.0_dp, deck%domain == 'auto')
         r%name = trim(c%name) // '_bend_twist_keep'
         cmp%compared = 'the full plate with D16, D26 kept instead of D16 = D26 = 0 (' // trim(scene%domain) // ')'
      else
         ! the paper's averaging: D16 = D26 = 0, on the smallest domain that allows (what 'auto' picks)
         r%variant(1) = "laminate.bend_twist='drop'"
         d = deck
         d%bend_twist = 'drop'
         call model_laminate(d, lmt, s)
         call choose_domain(d, s, stat, errmsg)
         r%cost_factor = 4.0_dp/quarters
         if (stat == 0) r%cost_factor = merge(1.0_dp, merge(2.0_dp, 4.0_dp, s%domain == 'half'), &
                                              s%domain == 'quarter')/quarters
         r%name = trim(c%name) // '_bend_twist_drop'
         cmp%compared = 'D16 = D26 = 0 (the paper''s averaging, section 3.1) instead of D16, D26 kept'
      end if
   end subroutine bend_twist_variant

   !> The relative change of each result estimated that the other model of c makes (else 0).
   pure function model_changes(c, lad) result(change)
      type(comparison_t), intent(in) :: c           !< its runs done
      type(ladder_t), intent(in) :: lad
      real(dp) :: change(nq)
      associate (q => lad%runs(c%run)%q, q_base => lad%runs(c%base)%q)
      change = merge(relative(q - q_base, error_scale(q_base)), 0.0_dp, lad%estimated)
      end associate
   end function model_changes

   !> The verdict of comparison c: the fuller model when a result that must meet the target
   !> changes by more than the target, else the simpler.
   pure function model_needed(c, change, lad) result(name)
      type(comparison_t), intent(in) :: c
      real(dp), intent(in) :: change(nq)            !< the relative changes (model_changes)
      type(ladder_t), intent(in) :: lad
      character(len=:), allocatable :: name
      name = trim(merge(c%richer, c%simpler, any(lad%targeted .and. abs(change) > lad%target)))
   end function model_needed

   !> One model compared: the summary's items (what, the relative change of each result, the
   !> verdict: model_needed) and the terminal's lines, added to items and lines.
   subroutine comparison_report(items, lines, c, lad, chosen)
      type(summary_item_t), allocatable, intent(inout) :: items(:)   !< the summary
      character(len=msg_len), allocatable, intent(inout) :: lines(:)  !< the terminal's
      type(comparison_t), intent(in) :: c
      type(ladder_t), intent(in) :: lad
      integer, intent(in) :: chosen                 !< the run chosen
      real(dp) :: change(nq)
      character(len=msg_len) :: line
      character(len=:), allocatable :: head, key, why
      integer :: iq
      head = 'model: ' // trim(c%what) // ': '
      if (.not. made(c, lad%runs)) then             ! why: its note, or what became of its run
         associate (r => lad%runs(max(c%run, 1)))
         why = ' failed (' // trim(r%status) // ')'
         if (r%state == state_skipped) why = ' would pass &accuracy max_cpu_s'
         if (r%state == state_stopped) why = ' was stopped'
         why = 'the run ' // trim(r%name) // why
         end associate
         if (c%run == 0) why = trim(c%note)
         call summary_text(items, trim(c%what) // '_compared', 'none: ' // why)
         lines = [character(len=msg_len) :: lines, head // 'not compared: ' // why]
         return
      end if
      change = model_changes(c, lad)
      call summary_text(items, trim(c%what) // '_compared', trim(c%compared))
      call summary_text(items, trim(c%what) // '_compared_at', trim(lad%runs(c%base)%name))
      call summary_text(items, trim(c%what) // '_needed', model_needed(c, change, lad))
      line = ''
      do iq = 1, nq
         if (.not. lad%estimated(iq)) cycle
         key = trim(result_keys(iq)) // '_change_' // trim(c%what)
         call summary_real(items, key, key, '-', change(iq), 1.0_dp)
         write (line, '(a,1x,a,f8.3,a)') trim(line), trim(result_keys(iq)), 100.0_dp*change(iq), ' %'
      end do
      lines = [character(len=msg_len) :: lines, head // trim(c%compared) // ' changes' // trim(line)]
      if (c%base /= chosen) lines = [character(len=msg_len) :: lines, head // 'compared at run ' // &
         trim(lad%runs(c%base)%name) // ', not at the run chosen: ' // trim(c%at)]
      if (model_needed(c, change, lad) == c%richer) then
         line = head // 'more than the target ' // real_short(lad%target) // ': the scene requires '
         if (c%chosen_richer) line = trim(line) // ' the model of the run chosen (' // trim(c%richer) // ')'
         if (.not. c%chosen_richer) line = trim(line) // ' the other model (' // trim(c%richer) // &
            '): the results above are the simpler model''s (' // trim(c%simpler) // &
            '), and the fuller one moves them by more than the target'
      else
         line = head // 'within the target ' // real_short(lad%target) // ': '
         if (c%chosen_richer) line = trim(line) // ' the simpler model (' // trim(c%simpler) // ') would do as well'
         if (.not. c%chosen_richer) line = trim(line) // ' the model of the run chosen (' // trim(c%simpler) // &
            ') does as well as the fuller one (' // trim(c%richer) // ')'
      end if
      lines = [character(len=msg_len) :: lines, line]
   end subroutine comparison_report

   !> err/|value|, 0 when both are 0, huge when only value is.
   elemental real(dp) function relative(err, value)
      real(dp), intent(in) :: err, value            !< the error or change, the value
      relative = huge(1.0_dp)
      if (value /= 0.0_dp) relative = err/abs(value)
      if (value == 0.0_dp .and. err == 0.0_dp) relative = 0.0_dp
   end function relative

end module model_comparison
