!> contact_update: an experiment on the update of the assumed contact force
!> (issue 4, docs/PAPER.md "Time step and divergence"). Not part of the
!> solver; built by `make figures` as build/contact_update.
!>
!> Usage:  build/contact_update DECK UPDATE
!>
!>   UPDATE = 'fixed'    the paper's words (section 2.3): the force computed
!>                       from the law becomes the next assumed force,
!>                       F_assum <- F_cont, until eq. (17) holds
!>            'bracket'  this code's update (impact_driver: bracket_update),
!>                       a check of this program: it must give ./impact's
!>                       history
!>
!> Everything else is ./impact's 'paper' scheme (src/impact.f90): the same
!> first guess, the plate solved by Akay's iteration to eq. (18) under each
!> assumed force (eq. 19, 20), the impactor by eq. (21), the indentation by
!> eq. (13), the law by eq. (11)-(12), at most max_contact_iter contact
!> iterations per step; a step whose iteration did not meet eq. (17) keeps
!> its last assumed force, as ./impact does.
!>
!> Within a step, alpha depends on the assumed force F through the plate's
!> dynamic compliance at the impact point, c_p = share * [(K_L + 4/dt^2 M)^-1]
!> at the w freedom of the impact node (m/N), and the impactor's,
!> dt^2/(4 m) (eq. 21): d alpha/dF = -(c_p + dt^2/(4 m)) = -c in the linear
!> theory. The fixed-point map F -> F_law(alpha(F)) has the slope
!> -c dF_law/d alpha, so F_assum <- F_cont converges only while the law's
!> tangent stiffness dF/d alpha < 1/c. The program prints c_p, c, 1/c and
!> the indentation on the loading curve F = k alpha^1.5 above which
!> dF/d alpha = 1.5 k alpha^0.5 exceeds 1/c, and the largest slope
!> c dF_law/d alpha met along the run (the law's tangent on its current
!> branch, by central differences): above 1 the fixed point cannot converge
!> at that step. Run with 'bracket', that slope is the one along the
!> converged solution.
!>
!> A run whose energy error (column 13 of the history of ./impact:
!> E0 - kinetic - strain - indentation energy) falls below -E0 has created
!> more energy than the impact brought: it has diverged, and stops there
!> (diverged_at_us); the history up to that step is kept.
!>
!> Writes <prefix>_<UPDATE>.dat (prefix from the deck's &output): one row per
!> `every` steps, columns named with their units in its '#' header, and on
!> standard output one `key = value` line per result.
program contact_update
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use kinds, only: dp, msg_len
   use input_deck, only: deck_t, read_deck_file
   use contact_law, only: contact_history_t, contact_force, contact_commit
   use newmark, only: newmark_t, newmark_init, newmark_predictor, newmark_update, impactor_advance
   use impact_driver, only: model_t, plate_state_t, impactor_state_t, force_bracket_t, &
      build_model, factor_effective_matrix, plate_solve, mass_times, contact_area, &
      bracket_start, bracket_update, contact_converged, first_force_guess, &
      plate_kinetic_energy, plate_strain_energy, impact_deflection
   use global_matrix, only: global_solve
   implicit none

   !> Exponent of the loading curve F = k alpha^1.5, eq. (11).
   real(dp), parameter :: load_exponent = 1.5_dp
   !> Step of the central difference of the law's tangent, relative to alpha (-).
   real(dp), parameter :: rel_step = 1.0e-6_dp
   !> Created energy, as a multiple of E0, at which a run counts as diverged (-).
   real(dp), parameter :: diverged_ratio = 1.0_dp

   type(deck_t) :: deck
   type(model_t) :: model
   type(newmark_t) :: nm
   type(plate_state_t) :: plate
   type(impactor_state_t) :: imp, imp_new
   type(contact_history_t) :: hist
   type(force_bracket_t) :: br
   real(dp), allocatable :: mb(:), d_new(:), g_unit(:)
   real(dp) :: t, f_assum, f_cont, f_next, alpha, alpha_old, e0, e_ind, e_err
   real(dp) :: c_plate, c_impactor, c_total, alpha_star, peak_force, max_error, slope, max_slope, da
   integer :: stat, step, nstep, ic, nl_iter, unit, failed_steps, first_failed, iterations, nl_failed
   integer :: diverged_step
   logical :: nl_ok, contact_ok, use_fixed
   character(len=msg_len) :: errmsg, deck_path, update, path

   ! =====================================================================
   ! Arguments and deck
   ! =====================================================================
   errmsg = ''
   if (command_argument_count() /= 2) call fail('usage: contact_update DECK fixed|bracket')
   call get_command_argument(1, deck_path)
   call get_command_argument(2, update)
   if (update /= 'fixed' .and. update /= 'bracket') &
      call fail('update = '//trim(update)//': must be fixed or bracket')
   use_fixed = update == 'fixed'
   call read_deck_file(trim(deck_path), deck, stat, errmsg)
   if (stat /= 0) call fail('input: '//errmsg)
   if (deck%scheme /= 'paper') call fail(trim(deck_path)//': &analysis: scheme = '// &
      trim(deck%scheme)//": this experiment replaces the update of scheme = 'paper'")

   ! =====================================================================
   ! Model, left-hand matrix of eq. (19), the step's compliances
   ! =====================================================================
   call build_model(deck, model, stat, errmsg)
   if (stat /= 0) call fail(errmsg)
   nm = newmark_init(deck%dt)
   call factor_effective_matrix(model, nm, stat, errmsg)
   if (stat /= 0) call fail(errmsg)
   ! the plate's response to a unit force at the impact point (the point
   ! force of eq. 10: the decks of input/paper/update/ say load = 'point')
   if (deck%contact_load /= 'point') call fail(trim(deck_path)//': &contact: load = '// &
      trim(deck%contact_load)//": this experiment needs the paper's point force, load = 'point'")
   allocate (g_unit(model%msh%neq))
   g_unit = 0.0_dp
   g_unit(model%eq_impact) = model%force_share
   call global_solve(model%keff, g_unit, stat, errmsg)
   if (stat /= 0) call fail(errmsg)
   c_plate = g_unit(model%eq_impact)                       ! m/N, whole-plate force
   c_impactor = deck%dt**2/(4.0_dp*deck%mass)             ! m/N, eq. (21)
   c_total = c_plate + c_impactor
   alpha_star = (1.0_dp/(load_exponent*deck%k*c_total))**2 ! m, where 1.5 k alpha^0.5 = 1/c

   ! =====================================================================
   ! Time integration, ./impact's 'paper' scheme with the chosen update
   ! =====================================================================
   allocate (plate%d(model%msh%neq), plate%v(model%msh%neq), plate%a(model%msh%neq))
   allocate (mb(model%msh%neq), d_new(model%msh%neq))
   plate%d = 0.0_dp;  plate%v = 0.0_dp;  plate%a = 0.0_dp
   imp = impactor_state_t(w=0.0_dp, v=deck%velocity, f=0.0_dp)
   e0 = 0.5_dp*deck%mass*deck%velocity**2
   e_ind = 0.0_dp;  alpha_old = 0.0_dp
   peak_force = 0.0_dp;  max_error = 0.0_dp
   failed_steps = 0;  first_failed = 0;  iterations = 0;  nl_failed = 0;  diverged_step = 0
   max_slope = 0.0_dp
   nstep = nint(deck%t_end/deck%dt)

   path = trim(deck%prefix)//'_'//trim(update)//'.dat'
   open (newunit=unit, file=trim(path), status='replace', action='write', iostat=stat, iomsg=errmsg)
   if (stat /= 0) call fail(trim(path)//': '//errmsg)
   write (unit, '(a)') '# contact_update: '//trim(deck_path)//', update of the assumed force: '//trim(update)
   write (unit, '(a,es12.5,a,es12.5,a,es12.5,a)') '# c_plate = ', c_plate, ' m/N, c_impactor = ', &
      c_impactor, ' m/N, 1/c = ', 1.0_dp/c_total, ' N/m'
   write (unit, '(a)') '# 1 time_us (us)  2 force_N (N)  3 w_plate_mm (mm)  4 w_impactor_mm (mm)' // &
      '  5 indentation_mm (mm)  6 contact_iter (-)  7 converged (1 yes, 0 no)  8 energy_error_J (J)'

   time_steps: do step = 1, nstep
      t = real(step, dp)*deck%dt
      call mass_times(model, newmark_predictor(nm, plate%d, plate%v, plate%a), mb)
      d_new = plate%d
      contact_ok = .false.
      f_assum = first_force_guess(model, imp, impact_deflection(model, plate%d), deck%dt, hist)
      br = bracket_start()

      contact_iterations: do ic = 1, deck%max_contact_iter
         call contact_area(model, hist, f_assum)
         call plate_solve(model, mb, f_assum, plate%d, d_new, nl_iter, nl_ok, stat, errmsg)
         if (stat /= 0) call fail('plate solution: '//errmsg)
         if (.not. nl_ok) nl_failed = nl_failed + 1
         call impactor_advance(deck%mass, deck%dt, imp%w, imp%v, imp%f, f_assum, imp_new%w, imp_new%v)
         alpha = imp_new%w - impact_deflection(model, d_new)
         f_cont = contact_force(model%law, hist, alpha)
         if (contact_converged(f_assum, f_cont, deck%cr1)) then     ! eq. (17)
            contact_ok = .true.
            exit contact_iterations
         end if
         if (use_fixed) then
            f_next = f_cont                                          ! the paper's words
         else
            call bracket_update(br, f_assum, f_cont, f_next)         ! ./impact
         end if
         f_assum = f_next
      end do contact_iterations
      ic = min(ic, deck%max_contact_iter)
      iterations = iterations + ic
      if (.not. contact_ok) then
         failed_steps = failed_steps + 1
         if (first_failed == 0) first_failed = step
      end if

      ! -- slope of the fixed-point map at the accepted indentation
      if (alpha > 0.0_dp) then
         da = rel_step*alpha
         slope = c_total*abs(contact_force(model%law, hist, alpha + da) &
                             - contact_force(model%law, hist, alpha - da))/(2.0_dp*da)
         max_slope = max(max_slope, slope)
      end if

      call newmark_update(nm, plate%d, d_new, plate%v, plate%a)
      plate%d = d_new
      imp_new%f = f_assum
      e_ind = e_ind + 0.5_dp*(imp%f + imp_new%f)*(alpha - alpha_old)
      imp = imp_new
      call contact_commit(model%law, hist, alpha)
      alpha_old = alpha
      peak_force = max(peak_force, imp%f)

      e_err = e0 - (0.5_dp*deck%mass*imp%v**2 + plate_kinetic_energy(model, plate%v) &
                    + plate_strain_energy(model, plate%d) + e_ind)
      max_error = max(max_error, abs(e_err))
      if (mod(step, deck%every) == 0 .or. step == nstep .or. e_err < -diverged_ratio*e0) then
         write (unit, '(f12.4,4es16.7,2i6,es16.7)') t*1.0e6_dp, imp%f, &
            impact_deflection(model, plate%d)*1.0e3_dp, imp%w*1.0e3_dp, alpha*1.0e3_dp, &
            ic, merge(1, 0, contact_ok), e_err
      end if
      if (e_err < -diverged_ratio*e0) then
         diverged_step = step
         exit time_steps
      end if
   end do time_steps
   close (unit)

   ! =====================================================================
   ! Results
   ! =====================================================================
   write (output_unit, '(a)') 'deck = '//trim(deck_path)
   write (output_unit, '(a)') 'update = '//trim(update)
   write (output_unit, '(a,es12.5)') 'dt_s = ', deck%dt
   write (output_unit, '(a,i0,a,i0)') 'mesh = ', deck%ny, 'x', deck%nx
   write (output_unit, '(a,es12.5)') 'c_plate_m_per_N = ', c_plate
   write (output_unit, '(a,es12.5)') 'c_impactor_m_per_N = ', c_impactor
   write (output_unit, '(a,es12.5)') 'contracting_below_N_per_m = ', 1.0_dp/c_total
   write (output_unit, '(a,es12.5)') 'alpha_star_mm = ', alpha_star*1.0e3_dp
   write (output_unit, '(a,es12.5)') 'force_at_alpha_star_N = ', deck%k*alpha_star**load_exponent
   write (output_unit, '(a,es12.5)') 'peak_force_N = ', peak_force
   write (output_unit, '(a,es12.5)') 'max_fixed_point_slope = ', max_slope
   write (output_unit, '(a,i0)') 'steps = ', nstep
   write (output_unit, '(a,i0)') 'contact_iterations = ', iterations
   write (output_unit, '(a,i0)') 'unconverged_steps = ', failed_steps
   write (output_unit, '(a,i0)') 'unconverged_plate_solutions = ', nl_failed
   if (first_failed > 0) then
      write (output_unit, '(a,f10.2)') 'first_unconverged_us = ', real(first_failed, dp)*deck%dt*1.0e6_dp
   else
      write (output_unit, '(a)') 'first_unconverged_us = none'
   end if
   if (diverged_step > 0) then
      write (output_unit, '(a,f10.2)') 'diverged_at_us = ', real(diverged_step, dp)*deck%dt*1.0e6_dp
   else
      write (output_unit, '(a)') 'diverged_at_us = none'
   end if
   write (output_unit, '(a,es12.5)') 'initial_energy_J = ', e0
   write (output_unit, '(a,es12.5)') 'max_energy_error_J = ', max_error
   write (output_unit, '(a)') 'history = '//trim(path)

contains

   !> Stops with a message on standard error and exit status 1.
   subroutine fail(message)
      character(len=*), intent(in) :: message   !< what went wrong
      write (error_unit, '(a)') 'contact_update: error: '//trim(message)
      error stop 1
   end subroutine fail

end program contact_update
