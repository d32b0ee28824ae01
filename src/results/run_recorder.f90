!> The run recorder of the impact analysis (Fig. 3, "output"): everything a
!> run writes, kept out of the time loop. It owns the history file, the
!> HDF5 results file, the energy bookkeeping, the summary's figures, the
!> warnings and &analysis stop_on_warning. No module state: all of it is in
!> the record_t the main program holds.
!>
!>   record_open   before the first step: the files, row 0 (the impactor
!>                 touching the plate at v0)
!>   record_step   after every accepted step: energies, summary figures,
!>                 history row (every &output every steps), field
!>                 snapshots and the peak state in <prefix>.h5, warnings;
!>                 sets rec%stop when the run must end here (a divergence,
!>                 a warning with stop_on_warning, or a stop signal, SIGTERM
!>                 or SIGINT, src/system/process_stop.f90: status 'stopped by signal
!>                 N at step M', exit status 128 + N)
!>   record_close  at the end, or when a run fails: the summary, in
!>                 <prefix>_summary.dat and /summary, with its status
!>
!> Energies (whole plate, J): the impactor's kinetic energy; the plate's
!> kinetic and strain energy; the work of the contact force on the plate,
!> the trapezoidal rule of the load vectors at both ends of a step,
!> 1/2 (F_t p_t + F_t+dt p_t+dt)^T (D_t+dt - D_t) (which Newmark's rule
!> balances exactly against the plate's energy in the linear theory); the
!> energy the contact took, the impactor's work 1/2 (F_t + F_t+dt) dw_r less
!> that; and the balance, E0 less the four, which measures what the
!> integration lost (+) or created (-). A run whose balance goes below -E0
!> (it created more energy than the impact brought) has diverged and stops;
!> so does one whose state is not finite. The energies are computed on the
!> history rows only (every &output every steps: a strain energy and an
!> M x each), so with every > 1 the summary's energy maxima, the energy
!> warnings and the divergence stop see those rows.
module run_recorder
   use, intrinsic :: iso_fortran_env, only: error_unit, int64
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use kinds, only: dp, msg_len
   use number_text, only: int_str, real_short
   use deck_schema, only: deck_t
   use plate_model, only: model_t, back_face_strain, max_deflection, plate_kinetic_energy, plate_strain_energy
   use plate_solver, only: solver_t, contact_response, pattern_compliance
   use contact_iteration, only: contact_iteration_t, contact_area
   use contact_law, only: contact_history_t, contact_branch, law_tangent, branch_none
   use contact_load, only: load_pattern_t, pattern_mean
   use newmark, only: plate_state_t, impactor_t, impactor_compliance, newmark_init
   use scene_model, only: theory_warning, bending_deflection
   use result_files, only: column_t, history_columns, nhist, summary_item_t, summary_real, summary_integer, &
      summary_text, open_columns, write_history_row, reserve_summary, write_summary_file, col_time, col_force, &
      col_alpha, col_w_plate, col_w_impactor, col_v_impactor, col_strain_y, col_ke_impactor, col_ke_plate, &
      col_strain_energy, col_contact_work, col_contact_energy, col_energy_error, col_branch, col_contact_iter, &
      col_solves, nhist_strength, history_width, history_slot, col_failure_index, col_failure_mode
   use file_system, only: truncate_file, file_probe_t, open_probe, probe_size, close_probe
   use results_hdf5, only: results_file_t, results_open, results_append_history, results_state, results_flush, &
      results_leave, results_finish
   use damage_record, only: damage_t, damage_open, damage_step, damage_peak, damage_close
   use process_stop, only: stop_signal_caught
   implicit none
   private
   public :: record_t, record_open, record_step, record_close

   !> Deflection over thickness beyond which von Karman's theory of moderately
   !> large deflections is no longer trusted (a warning, not an error).
   real(dp), parameter :: von_karman_limit = 5.0_dp

   !> Kinds of warning, each given once (later ones are counted).
   integer, parameter :: warn_mixing = 1, warn_contact = 2, warn_deflection = 3, warn_unconverged = 4, &
                         warn_energy = 5, warn_indentation = 6, warn_drift = 7, warn_energy_lost = 8, nwarn = 8
   !> Energy the integration may create before it is warned, as a fraction
   !> of E0 (docs/STABILITY.md, "The energy bound"): the average acceleration
   !> rule conserves energy, so created energy is the time step's error in
   !> the contacts and the nonlinear terms, not rounding.
   real(dp), parameter :: energy_created_bound = 1.0e-3_dp
   !> Energy the integration may lose before it is warned, as a fraction of
   !> E0 (docs/STABILITY.md, "The energy bound"): the tolerances of eq. (17)
   !> and (18) and the time step's error in the contacts take a little at
   !> every step; more than this and the answer is no longer an impact's.
   real(dp), parameter :: energy_lost_bound = 1.0e-2_dp

   !> What a run has recorded so far.
   type :: record_t
      logical :: stop = .false.                  !< the run must end after this step
      character(len=:), allocatable :: stop_status   !< why (the summary's status)
      integer :: exit_status = 0                 !< the program's exit status then: 1, or 128 + a signal's number
      integer :: hist_unit = -1                  !< <prefix>_history.dat
      integer(int64) :: hist_bytes = 0           !< its length after the last whole row
      type(file_probe_t) :: hist_probe           !< it, open for its length on disk (write_history_row)
      character(len=:), allocatable :: hist_path
      type(results_file_t) :: h5                 !< <prefix>.h5
      type(damage_t) :: damage                   !< ply stresses and failure (&strength; src/results/damage_record.f90)
      integer :: ncol = nhist                    !< history columns of the run (history_width)
      integer :: every = 1, fields_every = 1, nstep = 0
      logical :: stop_on_warning = .false.
      real(dp) :: dt = 0, mass = 0, h = 0        !< time step (s), impactor mass (kg), plate thickness (m)
      character(len=:), allocatable :: edges
      ! -- energies (J)
      real(dp) :: e0 = 0, contact_work = 0, contact_energy = 0
      ! -- the previous step, for the work of the contact force
      type(impactor_t) :: imp_prev
      type(load_pattern_t) :: pattern_prev
      real(dp), allocatable :: d_prev(:)
      ! -- the summary's figures
      integer :: steps = 0, contacts = 0, contact_iterations = 0, max_contact_iter = 0, max_solves = 0
      integer :: unconverged_steps = 0, first_unconverged = 0, nonlinear_fallback_steps = 0
      integer :: contact_fallback_steps = 0, warnings = 0, mixed_seen = 0, solves_before = 0
      logical :: in_contact = .false.
      ! forces (N), times (s), deflections (m), strain (-), energies (J), w/h (-)
      real(dp) :: peak_force = 0, time_of_peak = 0, first_contact_start = -1, first_contact_end = -1
      real(dp) :: max_deflection = 0, max_strain_y = 0, max_energy_error = 0, energy_created = 0, energy_lost = 0
      real(dp) :: max_w_over_h = 0
      real(dp) :: w_bend_max = 0, diverged_at = -1
      ! compliances under the impactor over a step (m/N; c_plate -1: not measured), and the largest
      ! slope (c_plate + c_impactor) dF/d alpha of the paper's fixed-point force update (-)
      real(dp) :: c_plate = -1, c_impactor = 0, max_slope = 0
      logical :: warned(nwarn) = .false.
   end type record_t

contains

   !> Opens the history (title, deck echo, columns) and, with &output hdf5,
   !> <prefix>.h5; writes row 0. For scheme 'paper' it also measures the
   !> plate's compliance under the impactor over one step (one solve), for
   !> the summary's fixed-point diagnostics (docs/PAPER.md).
   subroutine record_open(rec, deck, model, solver, imp, stat, errmsg)
      type(record_t), intent(out) :: rec            !< the record
      type(deck_t), intent(in) :: deck              !< the effective deck
      type(model_t), intent(in) :: model            !< the model
      type(solver_t), intent(inout) :: solver       !< the solver (one response for c_plate)
      type(impactor_t), intent(in) :: imp     !< the impactor at t = 0
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      type(contact_history_t) :: fresh
      real(dp) :: row(nhist_strength)
      character(len=24), allocatable :: names(:)
      character(len=96), allocatable :: texts(:)
      type(column_t) :: col
      integer :: c

      rec%every = deck%every;  rec%fields_every = deck%fields_every
      rec%nstep = nint(deck%t_end/deck%dt)
      rec%stop_on_warning = deck%stop_on_warning
      rec%dt = deck%dt;  rec%mass = deck%mass;  rec%h = deck%h
      rec%edges = deck%edges
      rec%e0 = 0.5_dp*deck%mass*deck%velocity**2
      rec%imp_prev = imp
      rec%d_prev = [(0.0_dp, c = 1, model%msh%neq)]
      call contact_area(model, fresh, 0.0_dp, rec%pattern_prev)
      rec%c_impactor = impactor_compliance(newmark_init(deck%dt), imp)
      if (deck%scheme == 'paper') then
         call contact_response(solver, rec%pattern_prev, stat, errmsg)
         if (stat /= 0) return
         rec%c_plate = pattern_compliance(solver, rec%pattern_prev)
      end if

      call reserve_summary(deck, stat, errmsg)
      if (stat /= 0) return
      ! -- with &strength: the ply stresses and failure indices (src/results/damage_record.f90)
      call damage_open(rec%damage, deck, model)
      rec%ncol = history_width(rec%damage%active)
      ! (filled in a loop: gfortran 12 garbles an array constructor of a
      ! constant's components with a variable implied-do bound)
      allocate (names(rec%ncol), texts(rec%ncol))
      do c = 1, rec%ncol
         col = history_columns(c)
         names(c) = col%file_name
         texts(c) = col%meaning // ' (' // trim(col%file_unit) // ')'
      end do

      call open_columns(deck, '_history.dat', 'impact: history of a low-velocity impact (Choi, Hong & Lee 1991)', &
         names, texts, rec%hist_unit, rec%hist_path, stat, errmsg, align=history_slot)
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
      call write_row(rec, row, stat, errmsg)
   end subroutine record_open

   !> Records the step just accepted (module header). ic is the step's
   !> contact iterations, converged whether its iterations met eq. (17)
   !> and (18) (force_update = 'plain' goes on without).
   subroutine record_step(rec, step, model, solver, plate, imp, hist, cit, ic, converged, stat, errmsg)
      type(record_t), intent(inout) :: rec               !< the record
      integer, intent(in) :: step                        !< the step
      type(model_t), intent(in) :: model                 !< the model
      type(solver_t), intent(in) :: solver               !< the solver (its counters)
      type(plate_state_t), intent(in) :: plate           !< the plate at t + dt
      type(impactor_t), intent(in) :: imp          !< the impactor at t + dt
      type(contact_history_t), intent(in) :: hist        !< the contact history before this step's commit
      type(contact_iteration_t), intent(in) :: cit       !< the step's contact force, indentation, area
      integer, intent(in) :: ic                          !< contact iterations of the step
      logical, intent(in) :: converged                   !< its iterations converged
      integer, intent(out) :: stat                       !< 0 on success
      character(len=*), intent(inout) :: errmsg          !< reason on failure
      real(dp) :: t, w_plate, strain_y, work, row(nhist_strength), w_bend, w_rigid
      integer :: solves

      stat = 0
      t = real(step, dp)*rec%dt
      rec%steps = step
      solves = solver%solves - rec%solves_before
      rec%solves_before = solver%solves

      ! -- energies: the contact force's work on the plate, the contact's share
      work = 0.5_dp*(rec%imp_prev%f*pattern_mean(rec%pattern_prev, plate%d - rec%d_prev) &
                     + imp%f*pattern_mean(cit%pattern, plate%d - rec%d_prev))
      rec%contact_work = rec%contact_work + work
      rec%contact_energy = rec%contact_energy + 0.5_dp*(rec%imp_prev%f + imp%f)*(imp%w - rec%imp_prev%w) - work
      rec%imp_prev = imp
      rec%pattern_prev = cit%pattern
      rec%d_prev = plate%d

      ! -- the summary's figures
      w_plate = pattern_mean(cit%pattern, plate%d)
      strain_y = back_face_strain(model, plate%d)
      if (imp%f > rec%peak_force) then
         rec%peak_force = imp%f
         rec%time_of_peak = t
      end if
      if (imp%f > 0.0_dp .and. .not. rec%in_contact) then
         rec%in_contact = .true.
         rec%contacts = rec%contacts + 1
         if (rec%contacts == 1) rec%first_contact_start = t
      else if (imp%f <= 0.0_dp .and. rec%in_contact) then
         rec%in_contact = .false.
         if (rec%contacts == 1) rec%first_contact_end = t
      end if
      rec%max_deflection = nan_max(rec%max_deflection, abs(w_plate))
      rec%max_strain_y = nan_max(rec%max_strain_y, abs(strain_y))
      rec%contact_iterations = rec%contact_iterations + ic
      rec%max_contact_iter = max(rec%max_contact_iter, ic)
      rec%max_solves = max(rec%max_solves, solves)
      rec%max_w_over_h = nan_max(rec%max_w_over_h, max_deflection(model, plate%d)/rec%h)
      call bending_deflection(model%msh, rec%edges, plate%d, w_bend, stat, errmsg)
      if (stat /= 0) return
      rec%w_bend_max = nan_max(rec%w_bend_max, abs(w_bend))
      w_rigid = 0.0_dp     ! the rigid-body part of the deflection under the impactor (free edges)
      if (rec%edges == 'free') w_rigid = plate%d(model%msh%eq(3, model%msh%impact_node)) - w_bend
      if (rec%c_plate >= 0.0_dp) rec%max_slope = max(rec%max_slope, &
         (rec%c_plate + rec%c_impactor)*law_tangent(model%law, hist, cit%alpha))
      call damage_peak(rec%damage, step, t, imp%f, plate%d)

      ! -- the history row and the fields
      if (mod(step, rec%every) == 0 .or. step == rec%nstep) then
         row(col_time) = t;  row(col_force) = imp%f;  row(col_alpha) = cit%alpha
         row(col_w_plate) = w_plate;  row(col_w_impactor) = imp%w;  row(col_v_impactor) = imp%v
         row(col_strain_y) = strain_y
         row(col_ke_impactor) = 0.5_dp*rec%mass*imp%v**2
         row(col_ke_plate) = plate_kinetic_energy(model, plate%v)
         row(col_strain_energy) = plate_strain_energy(model, plate%d)
         row(col_contact_work) = rec%contact_work
         row(col_contact_energy) = rec%contact_energy
         row(col_energy_error) = rec%e0 - (row(col_ke_impactor) + row(col_ke_plate) + row(col_strain_energy) &
                                           + rec%contact_energy)
         row(col_branch) = contact_branch(hist, cit%alpha)
         if (imp%f <= 0.0_dp) row(col_branch) = branch_none
         row(col_contact_iter) = ic
         row(col_solves) = solves
         call damage_step(rec%damage, model, t, plate%d)
         if (rec%damage%active) then
            row(col_failure_index) = rec%damage%step_fi
            row(col_failure_mode) = rec%damage%step_mode
         end if
         rec%max_energy_error = nan_max(rec%max_energy_error, abs(row(col_energy_error)))
         rec%energy_created = nan_max(rec%energy_created, -row(col_energy_error))
         rec%energy_lost = nan_max(rec%energy_lost, row(col_energy_error))
         call write_row(rec, row, stat, errmsg)
         if (stat /= 0) return
         if (row(col_energy_error) < -rec%e0) call stop_here('diverged at step ' // int_str(step), &
            'the run created more energy than the impact brought (energy balance ' &
            // real_short(row(col_energy_error)) // ' J, E0 = ' // real_short(rec%e0) // ' J): it has diverged')
      end if
      if (.not. (ieee_is_finite(w_plate) .and. ieee_is_finite(imp%f) .and. ieee_is_finite(imp%w))) &
         call stop_here('failed at step ' // int_str(step), 'the state is not finite (NaN or Inf): ' &
         // 'the iterations reached values the model cannot hold')
      call results_state(rec%h5, step, t, imp%f, plate%d, mod(step, rec%fields_every) == 0 .or. step == rec%nstep, &
                         stat, errmsg)
      if (stat /= 0) return

      ! -- warnings: fall-backs, deflections beyond von Karman's theory, a
      !    step that did not converge and went on (force_update = 'plain')
      if (solver%mixed_solves > rec%mixed_seen) then
         rec%mixed_seen = solver%mixed_solves
         rec%nonlinear_fallback_steps = rec%nonlinear_fallback_steps + 1
         call warn(warn_mixing, 'the nonlinear iteration (eq. 19) fell back to Anderson mixing (later such ' &
            // 'steps are counted in the summary, nonlinear_fallback_steps): ' // solver%mixing_note)
      end if
      if (cit%cut .or. cit%fell_back) then
         rec%contact_fallback_steps = rec%contact_fallback_steps + 1
         if (cit%fell_back) then
            call warn(warn_contact, 'the fixed-point force update stopped contracting; the step went on with ' &
               // 'the bracketed update (later such steps are counted in the summary, contact_fallback_steps)')
         else
            call warn(warn_contact, 'a plate solution failed under an assumed force; the force was cut (later ' &
               // 'such steps are counted in the summary, contact_fallback_steps)')
         end if
      end if
      if (rec%max_w_over_h > von_karman_limit) call warn(warn_deflection, 'the plate deflection is ' &
         // real_short(rec%max_w_over_h) // ' times the thickness, beyond the moderately large deflections of ' &
         // 'von Karman''s theory (w/h > ' // real_short(von_karman_limit) // '): the results are outside ' &
         // 'the model''s validity')
      if (rec%energy_created > energy_created_bound*rec%e0) call warn(warn_energy, 'the integration has ' &
         // 'created ' // real_short(rec%energy_created/rec%e0) // ' E0 of energy (more than ' &
         // real_short(energy_created_bound) // ' E0): the time step is too long for this scene''s contacts; ' &
         // 'halve dt until max_energy_created_J settles (docs/STABILITY.md)')
      if (rec%energy_lost > energy_lost_bound*rec%e0) call warn(warn_energy_lost, 'the integration has ' &
         // 'lost ' // real_short(rec%energy_lost/rec%e0) // ' E0 of energy (more than ' &
         // real_short(energy_lost_bound) // ' E0): the time step is too long for this scene''s contacts, ' &
         // 'or C_r1, C_r2 too loose; halve dt until max_energy_lost_J settles (docs/STABILITY.md)')
      if (cit%alpha > rec%h) call warn(warn_indentation, 'the indentation (' // real_short(cit%alpha*1.0e3_dp) &
         // ' mm) exceeds the plate thickness (' // real_short(rec%h*1.0e3_dp) // ' mm): the impactor is ' &
         // 'going through the plate, beyond the contact law (eq. 11-12) and the plate theory')
      if (abs(w_rigid) > rec%w_bend_max .and. rec%w_bend_max > 0.0_dp) call warn(warn_drift, 'the free ' &
         // 'plate has moved ' // real_short(abs(w_rigid)*1.0e3_dp) // ' mm as a rigid body under the ' &
         // 'impactor, more than its largest bending deflection (' // real_short(rec%w_bend_max*1.0e3_dp) &
         // ' mm): nothing holds it, and from here on its deflections are mostly flight, not bending')
      if (.not. converged) then
         rec%unconverged_steps = rec%unconverged_steps + 1
         if (rec%first_unconverged == 0) rec%first_unconverged = step
         call warn(warn_unconverged, 'the contact iteration (eq. 17) did not converge in max_contact_iter ' &
            // 'iterations; with force_update = ''plain'' the step keeps its last assumed force and the run ' &
            // 'goes on (later such steps are counted in the summary, unconverged_steps)')
      end if

      ! -- a stop signal (SIGTERM, SIGINT): the run ends after this step
      if (stop_signal_caught() > 0) then
         call stop_here('stopped by signal ' // int_str(stop_signal_caught()) // ' at step ' // int_str(step), '')
         rec%exit_status = 128 + stop_signal_caught()
      end if

   contains

      !> A warning on standard error naming the step and time, given once per
      !> kind; counted in the summary. With &analysis stop_on_warning the
      !> run stops after this step.
      subroutine warn(kind, message)
         integer, intent(in) :: kind
         character(len=*), intent(in) :: message
         integer :: ios
         character(len=msg_len) :: why
         if (rec%warned(kind)) return
         rec%warned(kind) = .true.
         rec%warnings = rec%warnings + 1
         write (error_unit, '(a,i0,a,es11.4,a)') 'impact: warning: step ', step, ' (t = ', t, ' s): ' // message
         call results_flush(rec%h5, ios, why)      ! the results up to the warning, on disk
         if (ios /= 0 .and. stat == 0) then
            stat = ios
            errmsg = why
         end if
         if (rec%stop_on_warning) call stop_here('stopped at step ' // int_str(step) // ' by the warning ' &
            // '(&analysis stop_on_warning = .true.)', '')
      end subroutine warn

      subroutine stop_here(status, message)
         character(len=*), intent(in) :: status, message
         if (rec%stop) return
         rec%stop = .true.
         rec%stop_status = status
         rec%exit_status = 1
         if (status(1:min(8, len(status))) == 'diverged') rec%diverged_at = t
         if (len(message) > 0) write (error_unit, '(a)') 'impact: error: step ' // int_str(step) // ': ' // message
      end subroutine stop_here

   end subroutine record_step

   !> Writes the summary (<prefix>_summary.dat and /summary of <prefix>.h5)
   !> with the run's status and closes the files; after a linear run whose
   !> deflection needed the nonlinear theory, warns (src/model/scene_model.f90).
   !> Safe to call after any failure of record_open or record_step.
   subroutine record_close(rec, deck, model, solver, status, hist, imp, cpu_s, unit, stat, errmsg)
      type(record_t), intent(inout) :: rec          !< the record
      type(deck_t), intent(in) :: deck              !< the effective deck
      type(model_t), intent(in) :: model            !< the model (its scene, for the theory warning)
      type(solver_t), intent(in) :: solver          !< the solver (its counters)
      character(len=*), intent(in) :: status        !< 'completed', 'failed at step N (t = ...)', ...
      type(contact_history_t), intent(in) :: hist   !< the contact history at the end
      type(impactor_t), intent(in) :: imp     !< the impactor at the end
      real(dp), intent(in) :: cpu_s                 !< cpu time of the run (s)
      integer, intent(in) :: unit                   !< where the last words go (standard output)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure (the first)
      type(summary_item_t), allocatable :: s(:)
      character(len=msg_len) :: text, dtext
      real(dp) :: duration
      logical :: ended, short
      integer :: ios, dstat

      call theory_warning(model%scene, rec%w_bend_max, short, text)
      if (short) then
         write (error_unit, '(a)') 'impact: warning: ' // trim(text)
         rec%warnings = rec%warnings + 1
      end if
      if (rec%warnings > 0) write (error_unit, '(a)') 'impact: ' // int_str(rec%warnings) // ' warning(s) above; ' &
         // 'steps with a fall-back: nonlinear ' // int_str(rec%nonlinear_fallback_steps) // ', contact ' &
         // int_str(rec%contact_fallback_steps) // '; largest w/h ' // real_short(rec%max_w_over_h)

      ! -- first contact: its duration, or the time in contact so far
      ended = rec%contacts == 0 .or. rec%first_contact_end >= 0.0_dp
      duration = 0.0_dp
      if (rec%contacts >= 1) duration = merge(rec%first_contact_end, real(rec%steps, dp)*rec%dt, ended) &
                                        - rec%first_contact_start
      allocate (s(0))
      call summary_text(s, 'status', status)
      call summary_real(s, 'peak_force_N', 'peak_force', 'N', rec%peak_force, 1.0_dp)
      call summary_real(s, 'time_of_peak_us', 'time_of_peak', 's', rec%time_of_peak, 1.0e6_dp)
      call summary_real(s, 'contact_duration_us', 'contact_duration', 's', duration, 1.0e6_dp)
      call summary_text(s, 'first_contact_ended', trim(merge('true ', 'false', ended)))
      call summary_integer(s, 'contacts', rec%contacts)
      call summary_real(s, 'max_deflection_mm', 'max_deflection', 'm', rec%max_deflection, 1.0e3_dp)
      call summary_real(s, 'max_strain_y_back', 'max_strain_y_back', '-', rec%max_strain_y, 1.0_dp)
      call summary_real(s, 'permanent_indentation_mm', 'permanent_indentation', 'm', hist%alpha_0, 1.0e3_dp)
      call summary_real(s, 'rebound_velocity_m_s', 'rebound_velocity', 'm/s', -imp%v, 1.0_dp)
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
      call time_or_none('first_unconverged_us', 'first_unconverged', real(rec%first_unconverged, dp)*rec%dt, &
                        rec%first_unconverged > 0)
      call time_or_none('diverged_at_us', 'diverged_at', rec%diverged_at, rec%diverged_at >= 0.0_dp)
      call summary_integer(s, 'nonlinear_fallback_steps', rec%nonlinear_fallback_steps)
      call summary_integer(s, 'contact_fallback_steps', rec%contact_fallback_steps)
      call summary_real(s, 'max_w_over_h', 'max_w_over_h', '-', rec%max_w_over_h, 1.0_dp)
      if (rec%c_plate >= 0.0_dp) then
         call summary_real(s, 'plate_compliance_m_per_N', 'plate_compliance', 'm/N', rec%c_plate, 1.0_dp)
         call summary_real(s, 'impactor_compliance_m_per_N', 'impactor_compliance', 'm/N', rec%c_impactor, 1.0_dp)
         call summary_real(s, 'max_fixed_point_slope', 'max_fixed_point_slope', '-', rec%max_slope, 1.0_dp)
      end if
      call damage_close(rec%damage, model, s, rec%h5, dstat, dtext)
      call summary_integer(s, 'warnings', rec%warnings)
      call summary_real(s, 'cpu_s', 'cpu', 's', cpu_s, 1.0_dp)

      if (rec%hist_unit >= 0) close (rec%hist_unit, iostat=ios)
      rec%hist_unit = -1
      call close_probe(rec%hist_probe)
      if (.not. allocated(rec%hist_path)) rec%hist_path = deck%prefix // '_history.dat'
      call write_summary_file(deck, s, stat, errmsg)
      if (dstat /= 0 .and. stat == 0) then
         stat = dstat
         errmsg = dtext
      end if
      call results_finish(rec%h5, status, s, ios, text)
      if (ios /= 0 .and. stat == 0) then
         stat = ios
         errmsg = text
      end if
      write (unit, '(a)') 'history: ' // rec%hist_path
      write (unit, '(a)') 'summary: ' // deck%prefix // '_summary.dat'
      if (deck%hdf5) write (unit, '(a)') 'results: ' // deck%prefix // '.h5'
      write (unit, '(a,es12.5,a,f9.2,a,i0,a,es12.5,a,f8.3,a)') 'peak force ', rec%peak_force, ' N at ', &
         rec%time_of_peak*1.0e6_dp, ' us; contacts ', rec%contacts, '; max deflection ', &
         rec%max_deflection*1.0e3_dp, ' mm; cpu ', cpu_s, ' s'

   contains

      subroutine time_or_none(key, name, time, given)
         character(len=*), intent(in) :: key, name
         real(dp), intent(in) :: time
         logical, intent(in) :: given
         if (given) then
            call summary_real(s, key, name, 's', time, 1.0e6_dp)
         else
            call summary_text(s, key, 'none')
         end if
      end subroutine time_or_none

   end subroutine record_close

   ! ============================================================== helpers

   !> A history row to the file and to <prefix>.h5.
   subroutine write_row(rec, row, stat, errmsg)
      type(record_t), intent(inout) :: rec
      real(dp), intent(in) :: row(nhist_strength)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      character(len=msg_len) :: iomsg
      integer :: ios
      call write_history_row(rec%hist_unit, rec%hist_probe, row(:rec%ncol), rec%hist_bytes, stat, iomsg)
      if (stat /= 0) then
         ! a full disk, the file-size limit: the history is cut back to its
         ! last whole row, so that every row it keeps reads
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
      real(dp), intent(in) :: a, b
      if (a /= a) then
         nan_max = a
      else if (b /= b .or. b > a) then
         nan_max = b
      else
         nan_max = a
      end if
   end function nan_max


end module run_recorder
