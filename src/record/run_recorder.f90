!> The run's record (Fig. 3, "output"), kept out of the time loop: the
!> history file and <prefix>.h5, the energy balance, the summary's figures,
!> the warnings. record_open before the first step (row 0), record_step after
!> every accepted step (rec%stop: the run ends there), record_close at the
!> end or on a failure. More: docs/OUTPUT.md.
module run_recorder
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit, int64
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
   use kinds, only: dp, msg_len
   use number_text, only: int_str, real_short
   use deck_schema, only: deck_t
   use plate_model, only: model_t, back_face_strain, max_deflection, plate_kinetic_energy, plate_strain_energy
   use plate_solver, only: solver_t
   use contact_iteration, only: step_state_t, contact_iteration_t, contact_area
   use contact_law, only: contact_history_t, contact_branch, law_tangent, branch_none
   use contact_load, only: load_pattern_t, pattern_mean
   use newmark, only: newmark_t, impactor_t, impactor_compliance
   use scene_model, only: theory_warning, bending_deflection
   use result_files, only: column_t, history_columns, nhist, summary_item_t, summary_real, summary_integer, &
      summary_text, keep_failure, open_history, write_history_row, reserve_summary, write_summary_file, col_time, col_force, &
      col_alpha, col_w_plate, col_w_impactor, col_v_impactor, col_strain_y, col_ke_impactor, col_ke_plate, &
      col_strain_energy, col_contact_work, col_contact_energy, col_energy_error, col_branch, col_contact_iter, &
      col_solves, nhist_damage, history_width, col_failure_index, col_failure_mode, col_damage_dissipated
   use file_system, only: truncate_file, file_probe_t, open_probe, probe_size, close_probe
   use results_hdf5, only: results_file_t, results_open, results_append_history, results_state, results_tick, &
      results_flush, results_leave, results_closing, results_finish
   use damage_record, only: damage_t, damage_open, damage_step, damage_peak, damage_close
   use plate_damage, only: damage_wanted
   use progress_line, only: progress_t, progress_start, progress_step, progress_end
   use step_peak, only: peak_track_t, peak_sample, peak_between, zero_crossing
   implicit none
   private
   public :: record_t, record_settings, record_open, record_step, record_close, nwarn

   !> w/h beyond which von Karman's moderately large deflections are not trusted (a warning).
   real(dp), parameter :: von_karman_limit = 5.0_dp

   !> Kinds of warning, each given once (later ones are counted).
   integer, parameter :: warn_mixing = 1, warn_contact = 2, warn_deflection = 3, warn_unconverged = 4, &
                         warn_energy = 5, warn_indentation = 6, warn_drift = 7, warn_energy_lost = 8, &
                         warn_substeps = 9, nwarn = 9
   !> Energy the integration may create (lose) before it is warned, a fraction
   !> of E0: the time step's error (docs/STABILITY.md, "The energy bound").
   real(dp), parameter :: energy_created_bound = 1.0e-3_dp, energy_lost_bound = 1.0e-2_dp

   !> What a run has recorded so far (saved for a restart by src/record/restart_point.f90).
   type :: record_t
      logical :: stop = .false.                  !< the run must end after this step
      logical :: restart_due = .false.           !< the step ended with the files flushed: a restart point is due
      character(len=:), allocatable :: stop_status   !< why (the summary's status)
      integer :: exit_status = 0                 !< the program's exit status then (1)
      integer :: hist_unit = -1                  !< <prefix>_history.dat
      real(dp) :: u_damage = 0.0_dp, dissipated = 0.0_dp   !< ply damage: strain energy lost, energy dissipated (J)
      integer(int64) :: hist_bytes = 0           !< its length after the last whole row
      type(file_probe_t) :: hist_probe           !< it, open for its length on disk (write_history_row)
      character(len=:), allocatable :: hist_path
      type(results_file_t) :: h5                 !< <prefix>.h5
      type(damage_t) :: damage                   !< ply stresses and failure (&strength; src/results/damage_record.f90)
      integer :: ncol = nhist                    !< history columns of the run (history_width)
      integer :: every = 1, fields_every = 1, nstep = 0
      logical :: stop_on_warning = .false.
      real(dp) :: dt = 0, h = 0                  !< time step (s, Newmark's), plate thickness (m)
      real(dp) :: cpu_before = 0                 !< cpu time of the run before its restart (s)
      character(len=:), allocatable :: edges
      real(dp) :: e0 = 0, contact_work = 0, contact_energy = 0   !< energies (J)
      ! -- the previous step, for the work of the contact force
      type(impactor_t) :: imp_prev
      type(load_pattern_t) :: pattern_prev
      real(dp), allocatable :: d_prev(:)
      ! -- the summary's figures
      integer :: steps = 0, contacts = 0, contact_iterations = 0, max_contact_iter = 0, max_solves = 0
      integer :: unconverged_steps = 0, first_unconverged = 0, nonlinear_fallback_steps = 0
      integer :: contact_fallback_steps = 0, warnings = 0, mixed_seen = 0, solves_before = 0
      integer :: substepped_steps = 0            !< steps of scheme 'fast' taken in sub-steps (src/scheme/substeps.f90)
      logical :: in_contact = .false.
      ! samples of the largest force (N), deflection under the impactor (m), back-face strain (-)
      type(peak_track_t) :: force_peak, deflection_peak, strain_peak
      ! the first contact's start and end, interpolated (s; -1: not yet), and the step's indentation (m)
      real(dp) :: first_contact_start = -1, first_contact_end = -1, alpha_prev = 0
      real(dp) :: max_energy_error = 0, energy_created = 0, energy_lost = 0   !< energies (J)
      real(dp) :: max_w_over_h = 0, w_bend_max = 0, diverged_at = -1       !< w/h (-), m, s
      ! compliances under the impactor over a step (m/N; c_plate -1: none), largest fixed-point slope (-)
      real(dp) :: c_plate = -1, c_impactor = 0, max_slope = 0
      logical :: warned(nwarn) = .false.
      type(progress_t) :: progress               !< the progress line on standard error (src/record/progress_line.f90)
   end type record_t

   !> What record_step knows of the step it records, for its parts.
   type :: step_figures_t
      integer :: step = 0, ic = 0, solves = 0 !< the step, its contact iterations, eq. (19) solutions
      real(dp) :: t = 0                !< its time (s)
      real(dp) :: w_plate = 0          !< plate deflection under the impactor, pressure-weighted mean (m)
      real(dp) :: strain_y = 0         !< in-plane y strain on the back face at the gauge (-)
      real(dp) :: w_rigid = 0          !< free edges: the rigid-body part of the deflection under the impactor (m)
   end type step_figures_t

   !> A line of the warnings' table (step_warnings; the keys of its text: warning_text).
   type :: warning_check_t
      integer :: kind                                  !< the kind (warn_*), warned once per run
      logical :: due                                   !< its test holds at this step
      real(dp) :: figures(2)                           !< the numbers of its text (unused: 0)
      character(len=256) :: text                       !< its text
   end type warning_check_t

contains

   !> Opens the history and <prefix>.h5 and writes row 0.
   subroutine record_open(rec, deck, model, nm, imp, c_plate, stat, errmsg)
      type(record_t), intent(out) :: rec            !< the record
      type(deck_t), intent(in) :: deck              !< the effective deck
      type(model_t), intent(in) :: model            !< the model
      type(newmark_t), intent(in) :: nm             !< Newmark's constants (the time step)
      type(impactor_t), intent(in) :: imp           !< the impactor at t = 0
      real(dp), intent(in) :: c_plate               !< the plate's compliance (m/N; -1: not measured)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      type(contact_history_t) :: fresh
      real(dp) :: row(nhist_damage)
      character(len=24), allocatable :: names(:)
      character(len=96), allocatable :: texts(:)
      type(column_t) :: col
      integer :: c
      call record_settings(rec, deck, model, nm)
      rec%e0 = 0.5_dp*imp%mass*imp%v**2
      rec%imp_prev = imp
      rec%d_prev = [(0.0_dp, c = 1, model%msh%neq)]
      call contact_area(model, fresh, 0.0_dp, rec%pattern_prev)
      rec%c_impactor = impactor_compliance(nm, imp)
      rec%c_plate = c_plate
      call reserve_summary(deck, stat, errmsg)
      if (stat /= 0) return
      ! (a loop: gfortran 12 garbles an array constructor of a constant's components here)
      allocate (names(rec%ncol), texts(rec%ncol))
      do c = 1, rec%ncol
         col = history_columns(c)
         names(c) = col%file_name
         texts(c) = col%meaning // ' (' // trim(col%file_unit) // ')'
      end do
      call open_history(deck, 'impact: history of a low-velocity impact (Choi, Hong & Lee 1991)', &
         names, texts, rec%hist_unit, rec%hist_path, stat, errmsg)
      if (stat /= 0) return
      call open_probe(rec%hist_path, rec%hist_probe, stat)
      if (stat /= 0) then
         errmsg = rec%hist_path // ': cannot open it to read its length'
         return
      end if
      rec%hist_bytes = probe_size(rec%hist_probe)
      call results_open(deck, model%msh, rec%h5, stat, errmsg)
      if (stat /= 0) return
      row = 0.0_dp
      row(col_v_impactor) = imp%v
      row(col_ke_impactor) = rec%e0
      ! -- row 0 is the first sample of the summary's peaks (the plate at rest, the impactor touching)
      call peak_sample(rec%force_peak, 0.0_dp, 0.0_dp)
      call peak_sample(rec%deflection_peak, 0.0_dp, 0.0_dp)
      call peak_sample(rec%strain_peak, 0.0_dp, 0.0_dp)
      call write_row(rec, row, stat, errmsg)
      call progress_start(rec%progress, rec%nstep, deck%t_end)
      if (stat == 0) call results_flush(rec%h5, stat, errmsg)     ! row 0 in every file: the first restart point
   end subroutine record_open

   !> The settings the record keeps (of the deck, the time step; &strength's damage_record).
   subroutine record_settings(rec, deck, model, nm)
      type(record_t), intent(inout) :: rec          !< the record
      type(deck_t), intent(in) :: deck              !< the effective deck
      type(model_t), intent(in) :: model            !< the model
      type(newmark_t), intent(in) :: nm             !< Newmark's constants (the time step)
      rec%every = deck%every;  rec%fields_every = deck%fields_every
      rec%nstep = nint(deck%t_end/nm%dt)
      rec%stop_on_warning = deck%stop_on_warning
      rec%dt = nm%dt;  rec%h = deck%h
      rec%edges = deck%edges
      call damage_open(rec%damage, deck, model)
      rec%ncol = history_width(rec%damage%active, damage_wanted(deck))
   end subroutine record_settings

   !> Records the step just accepted (its contact history not yet committed).
   subroutine record_step(rec, step, model, solver, st, stat, errmsg)
      type(record_t), intent(inout) :: rec               !< the record
      integer, intent(in) :: step                        !< the step
      type(model_t), intent(in) :: model                 !< the model
      type(solver_t), intent(in) :: solver               !< the solver (its counters)
      type(step_state_t), intent(in) :: st               !< the step accepted, its contact history not yet committed
      integer, intent(out) :: stat                       !< 0 on success
      character(len=*), intent(inout) :: errmsg          !< reason on failure
      type(step_figures_t) :: fig
      real(dp) :: work
      stat = 0
      rec%restart_due = .false.
      associate (plate => st%plate, imp => st%imp)
      fig = step_figures_t(step=step, t=real(step, dp)*rec%dt, ic=st%cit%iterations, &
         solves=solver%solves - rec%solves_before, w_plate=pattern_mean(st%cit%pattern, plate%d), &
         strain_y=back_face_strain(model, plate%d))
      rec%steps = step
      rec%solves_before = solver%solves
      ! -- the step's contact work on the plate (trapezoidal rule, 1/2 (F_t p_t + F_t+dt p_t+dt)^T
      ! (D_t+dt - D_t)) and the energy the contact took, 1/2 (F_t + F_t+dt) dw_r less that work (J)
      work = 0.5_dp*(rec%imp_prev%f*pattern_mean(rec%pattern_prev, plate%d - rec%d_prev) &
                     + imp%f*pattern_mean(st%cit%pattern, plate%d - rec%d_prev))
      rec%contact_work = rec%contact_work + work
      rec%contact_energy = rec%contact_energy + 0.5_dp*(rec%imp_prev%f + imp%f)*(imp%w - rec%imp_prev%w) - work
      rec%imp_prev = imp
      rec%pattern_prev = st%cit%pattern
      rec%d_prev = plate%d
      rec%u_damage = solver%damage%u_lost
      rec%dissipated = solver%damage%dissipated
      call update_maxima(rec, fig, model, st, stat, errmsg)
      if (stat /= 0) return
      if (mod(step, rec%every) == 0 .or. step == rec%nstep) then
         call history_row(rec, fig, model, st, stat, errmsg)
         if (stat /= 0) return
      end if
      if (.not. (ieee_is_finite(fig%w_plate) .and. ieee_is_finite(imp%f) .and. ieee_is_finite(imp%w))) &
         call stop_here(rec, fig, 'failed at step ' // int_str(step), 'the state is not finite (NaN or Inf): ' &
         // 'the iterations reached values the model cannot hold')
      call results_state(rec%h5, step, fig%t, imp%f, plate%d, &
                         mod(step, rec%fields_every) == 0 .or. step == rec%nstep, stat, errmsg)
      if (stat /= 0) return
      call step_warnings(rec, fig, solver, st%cit, stat, errmsg)
      call progress_step(rec%progress, step, fig%t)
      ! once a second the files are flushed: a restart point is due (src/record/restart_point.f90)
      if (stat == 0) call results_tick(rec%h5, rec%restart_due, stat, errmsg)
      end associate
   end subroutine record_step

   !> The summary's running figures of every step: the peaks' samples
   !> (step_peak), the contacts, w/h, the iterations, the bending deflection
   !> (free edges: fig%w_rigid), the fixed-point slope, the ply stresses.
   subroutine update_maxima(rec, fig, model, st, stat, errmsg)
      type(record_t), intent(inout) :: rec               !< the record
      type(step_figures_t), intent(inout) :: fig         !< the step (in); its w_rigid (out)
      type(model_t), intent(in) :: model                 !< the model
      type(step_state_t), intent(in) :: st               !< the step accepted (record_step)
      integer, intent(out) :: stat                       !< 0 on success
      character(len=*), intent(inout) :: errmsg          !< reason on failure
      real(dp) :: w_bend, crossing
      associate (plate => st%plate, imp => st%imp, hist => st%hist, cit => st%cit)
      ! (a NaN force is not a sample: the peak force keeps the finite ones)
      if (.not. ieee_is_nan(imp%f)) call peak_sample(rec%force_peak, fig%t, imp%f)
      call peak_sample(rec%deflection_peak, fig%t, abs(fig%w_plate))
      call peak_sample(rec%strain_peak, fig%t, abs(fig%strain_y))
      ! the contacts; the first one starts and ends where alpha - alpha_0 crosses 0 (eq. 12, 13)
      crossing = zero_crossing(fig%t - rec%dt, rec%alpha_prev - hist%alpha_0, fig%t, &
                               cit%alpha - hist%alpha_0)
      if (imp%f > 0.0_dp .and. .not. rec%in_contact) then
         rec%in_contact = .true.
         rec%contacts = rec%contacts + 1
         if (rec%contacts == 1) rec%first_contact_start = crossing
      else if (imp%f <= 0.0_dp .and. rec%in_contact) then
         rec%in_contact = .false.
         if (rec%contacts == 1) rec%first_contact_end = crossing
      end if
      rec%alpha_prev = cit%alpha
      rec%contact_iterations = rec%contact_iterations + fig%ic
      rec%max_contact_iter = max(rec%max_contact_iter, fig%ic)
      rec%max_solves = max(rec%max_solves, fig%solves)
      rec%max_w_over_h = nan_max(rec%max_w_over_h, max_deflection(model, plate%d)/rec%h)
      call bending_deflection(model%msh, rec%edges, plate%d, w_bend, stat, errmsg)
      if (stat /= 0) return
      rec%w_bend_max = nan_max(rec%w_bend_max, abs(w_bend))
      fig%w_rigid = 0.0_dp
      if (rec%edges == 'free') fig%w_rigid = plate%d(model%msh%eq(3, model%msh%impact_node)) - w_bend
      if (rec%c_plate >= 0.0_dp) rec%max_slope = max(rec%max_slope, &
         (rec%c_plate + rec%c_impactor)*law_tangent(model%law, hist, cit%alpha))
      call damage_peak(rec%damage, fig%step, fig%t, imp%f, plate%d)
      end associate
   end subroutine update_maxima

   !> The history row of the step (every &output every steps, and the last);
   !> a balance below -E0 stops the run (diverged).
   subroutine history_row(rec, fig, model, st, stat, errmsg)
      type(record_t), intent(inout) :: rec               !< the record
      type(step_figures_t), intent(in) :: fig            !< the step
      type(model_t), intent(in) :: model                 !< the model
      type(step_state_t), intent(in) :: st               !< the step accepted (record_step)
      integer, intent(out) :: stat                       !< 0 on success
      character(len=*), intent(inout) :: errmsg          !< reason on failure
      real(dp) :: row(nhist_damage)
      associate (plate => st%plate, imp => st%imp, hist => st%hist, cit => st%cit)
      row(col_time) = fig%t;  row(col_force) = imp%f;  row(col_alpha) = cit%alpha
      row(col_w_plate) = fig%w_plate;  row(col_w_impactor) = imp%w;  row(col_v_impactor) = imp%v
      row(col_strain_y) = fig%strain_y
      ! -- energies (J), the balance E0 less them all: its largest, energy created (-) and lost (+)
      row(col_ke_impactor) = 0.5_dp*imp%mass*imp%v**2
      row(col_ke_plate) = plate_kinetic_energy(model, plate%v)
      row(col_strain_energy) = plate_strain_energy(model, plate%d) + rec%u_damage
      row(col_contact_work) = rec%contact_work
      row(col_contact_energy) = rec%contact_energy;  row(col_damage_dissipated) = rec%dissipated
      row(col_energy_error) = rec%e0 - (row(col_ke_impactor) + row(col_ke_plate) &
                                        + row(col_strain_energy) + rec%contact_energy + rec%dissipated)
      rec%max_energy_error = nan_max(rec%max_energy_error, abs(row(col_energy_error)))
      rec%energy_created = nan_max(rec%energy_created, -row(col_energy_error))
      rec%energy_lost = nan_max(rec%energy_lost, row(col_energy_error))
      row(col_branch) = contact_branch(hist, cit%alpha)
      if (imp%f <= 0.0_dp) row(col_branch) = branch_none
      row(col_contact_iter) = fig%ic
      row(col_solves) = fig%solves
      call damage_step(rec%damage, model, fig%t, plate%d)
      if (rec%damage%active) row(col_failure_index:col_failure_mode) = &
         [rec%damage%step_fi, real(rec%damage%step_mode, dp)]
      call write_row(rec, row, stat, errmsg)
      if (stat /= 0) return
      if (row(col_energy_error) < -rec%e0) call stop_here(rec, fig, 'diverged at step ' // int_str(fig%step), &
         'the run created more energy than the impact brought (energy balance ' &
         // real_short(row(col_energy_error)) // ' J, E0 = ' // real_short(rec%e0) // ' J): it has diverged')
      end associate
   end subroutine history_row

   !> The warnings of the step, from the table below: every step a test holds
   !> is counted (count_step), each kind warned once.
   subroutine step_warnings(rec, fig, solver, cit, stat, errmsg)
      type(record_t), intent(inout) :: rec               !< the record
      type(step_figures_t), intent(in) :: fig            !< the step
      type(solver_t), intent(in) :: solver               !< the solver (its fall-backs)
      type(contact_iteration_t), intent(in) :: cit       !< the step's contact iteration (converged: eq. 17, 18 met)
      integer, intent(out) :: stat                       !< 0 on success
      character(len=*), intent(inout) :: errmsg          !< reason on failure
      real(dp), parameter :: none(2) = 0.0_dp
      type(warning_check_t) :: table(10)
      integer :: k
      stat = 0
      table = [ &
         warning_check_t(warn_mixing, solver%mixed_solves > rec%mixed_seen, none, 'the nonlinear iteration ' &
            // '(eq. 19) fell back to Anderson mixing (later such steps are counted in the summary, ' &
            // 'nonlinear_fallback_steps): {note}'), &
         warning_check_t(warn_contact, cit%fell_back, none, 'the fixed-point force update stopped contracting; ' &
            // 'the step went on with the bracketed update (later such steps are counted in the summary, ' &
            // 'contact_fallback_steps)'), &
         warning_check_t(warn_contact, cit%cut .and. .not. cit%fell_back, none, 'a plate solution failed under ' &
            // 'an assumed force; the force was cut (later such steps are counted in the summary, ' &
            // 'contact_fallback_steps)'), &
         warning_check_t(warn_deflection, rec%max_w_over_h > von_karman_limit, [rec%max_w_over_h, &
            von_karman_limit], 'the plate deflection is {1} times the thickness, beyond the moderately large ' &
            // 'deflections of von Karman''s theory (w/h > {2}): the results are outside the model''s validity'), &
         warning_check_t(warn_energy, rec%energy_created > energy_created_bound*rec%e0, [rec%energy_created/rec%e0, &
            energy_created_bound], 'the integration has created {1} E0 of energy (more than {2} E0): the time ' &
            // 'step is too long for this scene''s contacts; halve dt until max_energy_created_J settles ' &
            // '(docs/STABILITY.md)'), &
         warning_check_t(warn_energy_lost, rec%energy_lost > energy_lost_bound*rec%e0, [rec%energy_lost/rec%e0, &
            energy_lost_bound], 'the integration has lost {1} E0 of energy (more than {2} E0): the time step is ' &
            // 'too long for this scene''s contacts, or C_r1, C_r2 too loose; halve dt until max_energy_lost_J ' &
            // 'settles (docs/STABILITY.md)'), &
         warning_check_t(warn_indentation, cit%alpha > rec%h, [cit%alpha*1.0e3_dp, rec%h*1.0e3_dp], 'the ' &
            // 'indentation ({1} mm) exceeds the plate thickness ({2} mm): the impactor is going through the ' &
            // 'plate, beyond the contact law (eq. 11-12) and the plate theory'), &
         warning_check_t(warn_drift, abs(fig%w_rigid) > rec%w_bend_max .and. rec%w_bend_max > 0.0_dp, &
            [abs(fig%w_rigid)*1.0e3_dp, rec%w_bend_max*1.0e3_dp], 'the free plate has moved {1} mm as a rigid ' &
            // 'body under the impactor, more than its largest bending deflection ({2} mm): nothing holds it, ' &
            // 'and from here on its deflections are mostly flight, not bending'), &
         warning_check_t(warn_unconverged, .not. cit%converged, none, 'the contact iteration (eq. 17) did not ' &
            // 'converge in max_contact_iter iterations; with force_update = ''plain'' the step keeps its last ' &
            // 'assumed force and the run goes on (later such steps are counted in the summary, ' &
            // 'unconverged_steps)'), &
         warning_check_t(warn_substeps, solver%substeps > 0, none, 'the iteration of the step (eq. 19 with ' &
            // 'the contact equation) did not converge; the step was taken again in ' // int_str(solver%substeps) &
            // ' sub-steps, which did (later such steps are counted in the summary, substepped_steps)') ]
      do k = 1, size(table)
         if (.not. table(k)%due) cycle
         call count_step(rec, table(k)%kind, fig%step, solver)
         if (.not. rec%warned(table(k)%kind)) &
            call warn(rec, fig, table(k)%kind, warning_text(table(k), solver), stat, errmsg)
      end do
   end subroutine step_warnings

   !> The summary's count of the steps of a warning's kind.
   subroutine count_step(rec, kind, step, solver)
      type(record_t), intent(inout) :: rec               !< the record
      integer, intent(in) :: kind                        !< the warning's kind (warn_*)
      integer, intent(in) :: step                        !< the step
      type(solver_t), intent(in) :: solver               !< the solver (its fall-backs so far)
      select case (kind)
      case (warn_mixing)
         rec%mixed_seen = solver%mixed_solves
         rec%nonlinear_fallback_steps = rec%nonlinear_fallback_steps + 1
      case (warn_contact)
         rec%contact_fallback_steps = rec%contact_fallback_steps + 1
      case (warn_unconverged)
         rec%unconverged_steps = rec%unconverged_steps + 1
         if (rec%first_unconverged == 0) rec%first_unconverged = step
      case (warn_substeps)
         rec%substepped_steps = rec%substepped_steps + 1
      end select
   end subroutine count_step

   !> A warning's text: {1}, {2} its figures, {note} the iteration's report.
   function warning_text(check, solver) result(text)
      type(warning_check_t), intent(in) :: check         !< the warning's line of the table
      type(solver_t), intent(in) :: solver               !< the solver (its mixing_note)
      character(len=:), allocatable :: text              !< the text
      integer :: k, i
      text = trim(check%text)
      do k = 1, 2                                        ! each key's first place
         i = index(text, '{' // int_str(k) // '}')
         if (i > 0) text = text(:i - 1) // real_short(check%figures(k)) // text(i + 3:)
      end do
      i = index(text, '{note}')
      if (i > 0) text = text(:i - 1) // solver%mixing_note // text(i + 6:)
   end function warning_text

   !> A warning on standard error, once per kind; with stop_on_warning the run stops.
   subroutine warn(rec, fig, kind, message, stat, errmsg)
      type(record_t), intent(inout) :: rec               !< the record
      type(step_figures_t), intent(in) :: fig            !< the step
      integer, intent(in) :: kind                        !< the warning's kind (warn_*)
      character(len=*), intent(in) :: message            !< its text
      integer, intent(inout) :: stat                     !< 0 on success; the first failure is kept
      character(len=*), intent(inout) :: errmsg          !< reason on failure
      integer :: ios
      character(len=msg_len) :: why
      if (rec%warned(kind)) return
      rec%warned(kind) = .true.
      rec%warnings = rec%warnings + 1
      call progress_end(rec%progress)           ! the terminal's progress line cleared first
      write (error_unit, '(a,i0,a,es11.4,a)') 'impact: warning: step ', fig%step, ' (t = ', fig%t, ' s): ' // message
      call results_flush(rec%h5, ios, why)      ! the results up to the warning, on disk
      call keep_failure(stat, errmsg, ios, why)
      if (rec%stop_on_warning) call stop_here(rec, fig, 'stopped at step ' // int_str(fig%step) // ' by the ' &
         // 'warning (&analysis stop_on_warning = .true.)', '')
   end subroutine warn

   !> The run must end after this step (rec%stop), status and exit 1; the first reason stays.
   subroutine stop_here(rec, fig, status, message)
      type(record_t), intent(inout) :: rec               !< the record
      type(step_figures_t), intent(in) :: fig            !< the step
      character(len=*), intent(in) :: status             !< the summary's status: 'diverged at step N', ...
      character(len=*), intent(in) :: message            !< why, for standard error ('' for nothing)
      if (rec%stop) return
      rec%stop = .true.
      rec%stop_status = status
      rec%exit_status = 1
      if (status(1:min(8, len(status))) == 'diverged') rec%diverged_at = fig%t
      if (len(message) > 0) write (error_unit, '(a)') 'impact: error: step ' // int_str(fig%step) // ': ' // message
   end subroutine stop_here

   !> Writes the summary with rec%stop_status and closes the files (safe after any failure).
   subroutine record_close(rec, deck, model, solver, st, cpu_s, stat, errmsg)
      type(record_t), intent(inout) :: rec          !< the record; its stop_status the run's status
      type(deck_t), intent(in) :: deck              !< the effective deck
      type(model_t), intent(in) :: model            !< the model (its scene, for the theory warning)
      type(solver_t), intent(in) :: solver          !< the solver (its counters)
      type(step_state_t), intent(in) :: st          !< the state at the end (impactor, contact history)
      real(dp), intent(in) :: cpu_s                 !< cpu time of the run (s)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure (the first)
      type(summary_item_t), allocatable :: s(:)
      character(len=msg_len) :: text, dtext
      integer :: ios, dstat
      real(dp) :: f_peak, t_peak, w_max, t_w
      logical :: short
      call progress_end(rec%progress)
      ! -- the end's warnings (a linear run that needed the nonlinear theory) and their count
      call theory_warning(model%scene, rec%w_bend_max, short, text)
      if (short) then
         write (error_unit, '(a)') 'impact: warning: ' // trim(text)
         rec%warnings = rec%warnings + 1
      end if
      if (rec%warnings > 0) write (error_unit, '(a)') 'impact: ' // int_str(rec%warnings) // ' warning(s) above; ' &
         // 'steps with a fall-back: nonlinear ' // int_str(rec%nonlinear_fallback_steps) // ', contact ' &
         // int_str(rec%contact_fallback_steps) // ', sub-stepped ' // int_str(rec%substepped_steps) &
         // '; largest w/h ' // real_short(rec%max_w_over_h)
      call run_summary(rec, solver, st, s)
      ! -- where the strain gauge of max_strain_y_back is (src/model/plate_model.f90, place_gauge)
      call summary_real(s, 'gauge_x_mm', 'gauge_x', 'm', model%gauge_xy(1), 1.0e3_dp)
      call summary_real(s, 'gauge_y_mm', 'gauge_y', 'm', model%gauge_xy(2), 1.0e3_dp)
      ! -- dt, mesh chosen from the scene (src/model/scene_settings.f90) when the deck gives none:
      ! the text after ' = ' of 'dt chosen = 2.0 us: ...'
      if (len_trim(deck%dt_chosen) > 0) call summary_text(s, 'dt_chosen', &
         trim(deck%dt_chosen(index(deck%dt_chosen, ' = ') + 3:)))
      if (len_trim(deck%mesh_chosen) > 0) call summary_text(s, 'mesh_chosen', &
         trim(deck%mesh_chosen(index(deck%mesh_chosen, ' = ') + 3:)))
      call results_closing(rec%h5)                  ! <prefix>.h5 open for its last words
      call damage_close(rec%damage, model, solver%damage, s, rec%h5, dstat, dtext)
      call summary_integer(s, 'warnings', rec%warnings)
      call summary_real(s, 'cpu_s', 'cpu', 's', cpu_s, 1.0_dp)
      if (rec%hist_unit >= 0) close (rec%hist_unit, iostat=ios)
      rec%hist_unit = -1
      call close_probe(rec%hist_probe)
      if (.not. allocated(rec%hist_path)) rec%hist_path = deck%prefix // '_history.dat'
      call write_summary_file(deck, s, stat, errmsg)
      call keep_failure(stat, errmsg, dstat, dtext)
      call results_finish(rec%h5, rec%stop_status, s, ios, text)
      call keep_failure(stat, errmsg, ios, text)
      ! -- the last words on standard output: the files, peak force, contacts, deflection, cpu time
      call peak_between(rec%force_peak, t_peak, f_peak)     ! as in the summary (above update_maxima)
      call peak_between(rec%deflection_peak, t_w, w_max)
      write (output_unit, '(a)') 'history: ' // rec%hist_path
      write (output_unit, '(a)') 'summary: ' // deck%prefix // '_summary.dat'
      if (deck%hdf5) write (output_unit, '(a)') 'results: ' // deck%prefix // '.h5'
      write (output_unit, '(a,es12.5,a,f9.2,a,i0,a,es12.5,a,f8.3,a)') 'peak force ', f_peak, &
         ' N at ', t_peak*1.0e6_dp, ' us; contacts ', rec%contacts, '; max deflection ', &
         w_max*1.0e3_dp, ' mm; cpu ', cpu_s, ' s'
   end subroutine record_close

   !> The summary's items from its status to the fixed-point diagnostics.
   subroutine run_summary(rec, solver, st, s)
      type(record_t), intent(in) :: rec             !< the record (its stop_status: the run's status)
      type(solver_t), intent(in) :: solver          !< the solver (its counters)
      type(step_state_t), intent(in) :: st          !< the state at the end (impactor, contact history)
      type(summary_item_t), allocatable, intent(out) :: s(:)   !< the items
      real(dp) :: duration, f_peak, t_peak, w_max, e_max, t_other
      logical :: ended
      ! -- first contact, from the first touch: its duration, or the time in contact so far
      ended = rec%contacts == 0 .or. rec%first_contact_end >= 0.0_dp
      duration = 0.0_dp
      if (rec%contacts >= 1) duration = merge(rec%first_contact_end, real(rec%steps, dp)*rec%dt, ended) &
                                        - rec%first_contact_start
      ! -- the peaks, refined between the steps (above update_maxima)
      call peak_between(rec%force_peak, t_peak, f_peak)
      call peak_between(rec%deflection_peak, t_other, w_max)
      call peak_between(rec%strain_peak, t_other, e_max)
      allocate (s(0))
      call summary_text(s, 'status', rec%stop_status)
      call summary_real(s, 'peak_force_N', 'peak_force', 'N', f_peak, 1.0_dp)
      call summary_real(s, 'time_of_peak_us', 'time_of_peak', 's', t_peak, 1.0e6_dp)
      call summary_real(s, 'peak_force_sampled_N', 'peak_force_sampled', 'N', rec%force_peak%v(2), 1.0_dp)
      call summary_real(s, 'time_of_peak_sampled_us', 'time_of_peak_sampled', 's', rec%force_peak%t(2), 1.0e6_dp)
      call summary_real(s, 'contact_duration_us', 'contact_duration', 's', duration, 1.0e6_dp)
      call summary_text(s, 'first_contact_ended', trim(merge('true ', 'false', ended)))
      call summary_integer(s, 'contacts', rec%contacts)
      call summary_real(s, 'max_deflection_mm', 'max_deflection', 'm', w_max, 1.0e3_dp)
      call summary_real(s, 'max_strain_y_back', 'max_strain_y_back', '-', e_max, 1.0_dp)
      call summary_real(s, 'permanent_indentation_mm', 'permanent_indentation', 'm', st%hist%alpha_0, 1.0e3_dp)
      call summary_real(s, 'rebound_velocity_m_s', 'rebound_velocity', 'm/s', -st%imp%v, 1.0_dp)
      call summary_real(s, 'initial_energy_J', 'initial_energy', 'J', rec%e0, 1.0_dp)
      call summary_real(s, 'max_energy_error_J', 'max_energy_error', 'J', rec%max_energy_error, 1.0_dp)
      call summary_real(s, 'max_energy_created_J', 'max_energy_created', 'J', rec%energy_created, 1.0_dp)
      call summary_real(s, 'max_energy_lost_J', 'max_energy_lost', 'J', rec%energy_lost, 1.0_dp)
      call summary_integer(s, 'steps', rec%steps)
      call summary_integer(s, 'plate_solves', solver%solves + solver%response_solves)
      call summary_integer(s, 'response_solves', solver%response_solves)
      call summary_integer(s, 'factorizations', solver%factorizations)
      call summary_integer(s, 'contact_iterations', rec%contact_iterations)
      call summary_integer(s, 'max_contact_iter', rec%max_contact_iter)
      call summary_integer(s, 'max_nonlinear_iter', rec%max_solves)
      call summary_integer(s, 'unconverged_steps', rec%unconverged_steps)
      call summary_real(s, 'first_unconverged_us', 'first_unconverged', 's', rec%first_unconverged*rec%dt, &
                        1.0e6_dp, rec%first_unconverged > 0, 'none')
      call summary_real(s, 'diverged_at_us', 'diverged_at', 's', rec%diverged_at, 1.0e6_dp, &
                        rec%diverged_at >= 0.0_dp, 'none')
      call summary_integer(s, 'nonlinear_fallback_steps', rec%nonlinear_fallback_steps)
      call summary_integer(s, 'contact_fallback_steps', rec%contact_fallback_steps)
      call summary_integer(s, 'substepped_steps', rec%substepped_steps)
      call summary_real(s, 'max_w_over_h', 'max_w_over_h', '-', rec%max_w_over_h, 1.0_dp)
      if (rec%c_plate >= 0.0_dp) then
         call summary_real(s, 'plate_compliance_m_per_N', 'plate_compliance', 'm/N', rec%c_plate, 1.0_dp)
         call summary_real(s, 'impactor_compliance_m_per_N', 'impactor_compliance', 'm/N', rec%c_impactor, 1.0_dp)
         call summary_real(s, 'max_fixed_point_slope', 'max_fixed_point_slope', '-', rec%max_slope, 1.0_dp)
      end if
   end subroutine run_summary

   ! ============================================================== helpers

   !> A history row to the file and to <prefix>.h5.
   subroutine write_row(rec, row, stat, errmsg)
      type(record_t), intent(inout) :: rec               !< the record
      real(dp), intent(in) :: row(nhist_damage)        !< the row, SI (its first rec%ncol columns are written)
      integer, intent(out) :: stat                       !< 0 on success
      character(len=*), intent(inout) :: errmsg          !< reason on failure
      character(len=msg_len) :: iomsg
      integer :: ios
      call write_history_row(rec%hist_unit, rec%hist_probe, row(:rec%ncol), rec%hist_bytes, stat, iomsg)
      if (stat /= 0) then
         ! a full disk, the file-size limit: the history is cut back to its last whole row
         errmsg = rec%hist_path // ': cannot write a row: ' // trim(iomsg)
         close (rec%hist_unit, iostat=ios)
         rec%hist_unit = -1
         call close_probe(rec%hist_probe)
         call truncate_file(rec%hist_path, rec%hist_bytes, ios)
         call results_leave(rec%h5)
         return
      end if
      call results_append_history(rec%h5, row(:rec%ncol), stat, errmsg)
   end subroutine write_row

   !> max(a, b) that keeps a NaN (Fortran's max may drop it).
   pure real(dp) function nan_max(a, b)
      real(dp), intent(in) :: a, b                       !< the largest so far, the new value
      nan_max = merge(a, b, ieee_is_nan(a) .or. .not. (ieee_is_nan(b) .or. b > a))
   end function nan_max

end module run_recorder
