!> validate: runs every check of docs/VALIDATION.md and writes its tables.
!>
!> Usage (from the repository root, after `make impact`):  make validate
!>   build/validate [REPORT]     (REPORT: default out/docs/VALIDATION.md;
!>                                make validate gives $(DOCS_DIR)/VALIDATION.md)
!>
!> The checks:
!>   1 Navier (FSDT) deflections and frequencies, cross-ply and orthotropic,
!>     a/h = 4..100, and the error against the mesh
!>   2 NAFEMS FV52 frequencies
!>   3 shear locking: a/h = 1000 against the classical plate
!>   4 nonlinear cylindrical bending of a strip (TWK Arts. 2-3)
!>   5 transient step pressure against the modal (Navier) solution, dt convergence
!>   6 the impactor on a rigid target against Hertz, with the paper's law
!>   7 the paper's Fig. 5: quarter against full plate
!>   8 energy balance, dissipation = loop area
!>   9 the element's shear rules; 10 the impact against the modal solution
!>  11 ply stresses against the Navier solution and the isotropic plate,
!>     each failure criterion against hand values
!> plus the program path: ./impact on the static, modes and pressure decks
!> gives the numbers the library gives.
!>
!> The program run is ./impact, or the one the environment variable
!> IMPACT_EXE names.
!>
!> Checks 1-5 call the analyses through the library (static_solve,
!> modal_solve, pressure_solve) on decks read from validation/decks and
!> varied here (mesh, thickness, load, time step); checks 6-8 run ./impact
!> on decks of validation/decks and read its result files.
!>
!> Output: build/validation/<table>.md (markdown tables), build/validation/*.dat
!> (data of the plots, column text with '#' headers), and REPORT, a copy of
!> the template validation/VALIDATION.md.in, whose blocks (between the
!> comments NAME:begin and NAME:end) make validate then fills with
!> build/validation/NAME.md (tools/impact_files.py fill). The plots are drawn
!> afterwards by validation/plots.gp (make validate). Exit status 1 when a
!> check fails.
program validate
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit, int64
   use kinds, only: dp, pi, msg_len
   use input_deck, only: deck_t, read_deck_file, validate_deck
   use materials, only: lamina_t, laminate_t, laminate_from_layup
   use plate_model, only: model_t, build_model
   use analysis_load, only: assemble_load
   use static_analysis, only: static_result_t, static_solve
   use modal_analysis, only: modal_result_t, modal_solve
   use pressure_analysis, only: pressure_result_t, pressure_solve
   use contact_law, only: contact_law_t
   use rigid_target, only: rigid_target_result_t, rigid_target_impact
   use navier_impact_solution, only: navier_problem_t, navier_result_t, navier_problem_from_deck, &
      navier_impact_run, load_hertz
   use shear_strain, only: shear_rule_t, shear_rule_names
   use element_matrices, only: element_geometry_t, element_geometry, element_stiffness
   use shape_functions, only: nen, node_xi
   use damage_record, only: damage_t, damage_open, damage_stresses, damage_points
   use failure_criteria, only: strength_t, failure_index, criterion_hashin, criterion_max_stress, &
      criterion_tsai_wu, mode_names
   use file_system, only: make_directories
   use child_process, only: spawn_program, wait_child
   use result_reader, only: summary_t, read_summary, summary_value, read_columns
   use reference_solutions, only: navier_sinusoidal_ply_stresses, isotropic_sinusoidal_stresses
   use reference_solutions, only: navier_series_t, navier_fsdt, navier_fsdt_static, navier_step_centre, &
      navier_frequencies, navier_clpt_centre, strip_deflection, hertz_impact_t, hertz_impact, &
      load_uniform, load_sinusoidal, load_central_force, edge_simply_supported, edge_clamped
   implicit none

   character(len=*), parameter :: out_dir = 'build/validation'
   character(len=*), parameter :: deck_dir = 'validation/decks'
   character(len=*), parameter :: template = 'validation/VALIDATION.md.in'
   !> The report: the command's argument, else this (make validate gives
   !> $(DOCS_DIR)/VALIDATION.md).
   character(len=*), parameter :: default_report = 'out/docs/VALIDATION.md'
   character(len=:), allocatable :: report
   !> Half-wave numbers kept in the Navier series of a uniform load (odd m, n <= this).
   integer, parameter :: mmax_series = 401
   !> Table cell width.
   integer, parameter :: cw = 72

   integer :: npass = 0, nfail = 0, su = 0, tu = 0
   real(dp) :: t0, t1, cpu_last
   integer(int64) :: wall0, clock_rate
   integer :: dir_stat                   !< making the output directories: 0 on success
   character(len=msg_len) :: dir_msg = ''  !< and what failed

   call cpu_time(t0)
   cpu_last = t0
   call system_clock(wall0, clock_rate)
   report = report_path()
   call make_directories(out_dir, dir_stat, dir_msg)
   if (dir_stat == 0) call make_directories(report_dir(report), dir_stat, dir_msg)
   if (dir_stat /= 0) call fail(dir_msg)
   open (newunit=su, file=out_dir // '/summary.md', status='replace', action='write')
   write (su, '(a)') '| check | quantity | worst error | tolerance | result |'
   write (su, '(a)') '|---|---|---|---|---|'

   call check_navier()
   call lap('check 1')
   call check_fv52()
   call lap('check 2')
   call check_locking()
   call lap('check 3')
   call check_strip()
   call lap('check 4')
   call check_transient()
   call lap('check 5')
   call check_hertz()
   call lap('check 6')
   call check_fig5()
   call lap('check 7')
   call check_energy()
   call lap('check 8')
   call check_element()
   call lap('check 9')
   call check_point_response()
   call lap('check 10')
   call check_ply_stresses()
   call lap('check 11')

   close (su)
   call copy_template()
   call cpu_time(t1)
   write (output_unit, '(a,i0,a,i0,a,f8.1,a)') 'validate: ', npass, ' passed, ', nfail, ' failed (cpu ', &
      t1 - t0, ' s); report: ' // report
   if (nfail > 0) error stop 1

contains

   ! ================================================================ check 1

   !> Navier (FSDT): centre deflection under uniform and sinusoidal load and
   !> the (1,1) frequency, a/h = 4..100, two plates; the error against the mesh.
   subroutine check_navier()
      character(len=20), parameter :: plates(2) = [character(len=20) :: 'navier_crossply', 'navier_orthotropic']
      character(len=40), parameter :: names(2) = [character(len=40) :: '[0/90/90/0], a = b', &
         '[0] (orthotropic), b = 2a']
      real(dp), parameter :: ratios(5) = [4.0_dp, 10.0_dp, 20.0_dp, 50.0_dp, 100.0_dp]
      integer, parameter :: meshes(5) = [1, 2, 4, 8, 16]
      !> FE against Navier at the deck's mesh (quarter 8 x 8; 8 x 16 for b = 2a)
      real(dp), parameter :: tol_w = 1.0e-4_dp, tol_f = 1.0e-4_dp
      !> the Navier series itself: halving the terms must change it by far less than tol_w
      real(dp), parameter :: tol_trunc = 1.0e-6_dp
      type(deck_t) :: deck0, deck
      type(laminate_t) :: lmt
      real(dp) :: wn(2), wf(2), err(3), worst_w, worst_f, scale_w, scale_f, omega_n, omega_f, trunc, e_prev(3)
      real(dp) :: worst_trunc
      real(dp) :: errs(3, size(meshes))
      integer :: ip, ia, il, k, du
      character(len=cw) :: cells(11)

      worst_w = 0.0_dp;  worst_f = 0.0_dp;  worst_trunc = 0.0_dp
      call table_open('navier', [character(len=cw) :: 'plate', 'a/h', 'w̄ uniform, Navier', 'FE', 'error', &
         'w̄ sinusoidal, Navier', 'FE', 'error', 'ω̄ (1,1), Navier', 'FE', 'error'])
      plates_loop: do ip = 1, size(plates)
         call load_deck(plates(ip), deck0)
         thickness: do ia = 1, size(ratios)
            deck = deck0
            deck%h = deck%a/ratios(ia)
            lmt = deck_laminate(deck)
            scale_w = 100.0_dp*deck%e2*deck%h**3/(deck%load_magnitude*deck%a**4)
            loads: do il = 1, 2
               deck%load_kind = merge('uniform   ', 'sinusoidal', il == 1)
               wn(il) = navier_centre(lmt, deck, mmax_series, trunc)
               worst_trunc = max(worst_trunc, trunc)
               wf(il) = fe_static_centre(deck)
               err(il) = wf(il)/wn(il) - 1.0_dp
            end do loads
            omega_n = navier_omega11(lmt, deck)
            omega_f = fe_frequency(deck, 1)*2.0_dp*pi
            err(3) = omega_f/omega_n - 1.0_dp
            scale_f = deck%a**2/deck%h*sqrt(deck%rho/deck%e2)
            worst_w = max(worst_w, maxval(abs(err(1:2))))
            worst_f = max(worst_f, abs(err(3)))
            cells = [character(len=cw) :: names(ip), num(ratios(ia), '(f6.0)'), &
               num(wn(1)*scale_w, '(f9.5)'), num(wf(1)*scale_w, '(f9.5)'), sci(err(1)), &
               num(wn(2)*scale_w, '(f9.5)'), num(wf(2)*scale_w, '(f9.5)'), sci(err(2)), &
               num(omega_n*scale_f, '(f9.5)'), num(omega_f*scale_f, '(f9.5)'), sci(err(3))]
            call table_row(cells)
         end do thickness
      end do plates_loop
      call table_close()
      call record('1 Navier, FSDT', 'centre deflection, FE (quarter 8 x 8) / Navier - 1', worst_w, tol_w)
      call record('1 Navier, FSDT', '(1,1) frequency, FE (quarter 8 x 8) / Navier - 1', worst_f, tol_f)
      call record('1 Navier, FSDT', 'reference: series with m, n <= 201 / with m, n <= 401 - 1', worst_trunc, &
         tol_trunc)

      ! -- the error against the mesh: cross-ply, a/h = 10
      call load_deck('navier_crossply', deck0)
      deck0%h = deck0%a/10.0_dp
      lmt = deck_laminate(deck0)
      call table_open('navier_mesh', [character(len=cw) :: 'quarter mesh', 'elements per half side', &
         'w uniform: error', 'rate', 'w sinusoidal: error', 'rate', 'ω (1,1): error', 'rate'])
      open (newunit=du, file=out_dir // '/navier_mesh.dat', status='replace', action='write')
      write (du, '(a)') '# check 1: FE error against Navier, cross-ply [0/90/90/0], a/h = 10, quarter n x n mesh'
      write (du, '(a)') '# columns: 1 n (elements per half side), 2 |error| w uniform (-), ' // &
         '3 |error| w sinusoidal (-), 4 |error| omega11 (-)'
      e_prev = 0.0_dp
      meshes_loop: do k = 1, size(meshes)
         deck = deck0
         deck%nx = meshes(k);  deck%ny = meshes(k)
         deck%load_kind = 'uniform'
         errs(1, k) = fe_static_centre(deck)/navier_centre(lmt, deck, mmax_series, trunc) - 1.0_dp
         deck%load_kind = 'sinusoidal'
         errs(2, k) = fe_static_centre(deck)/navier_centre(lmt, deck, mmax_series, trunc) - 1.0_dp
         if (meshes(k) <= 8) then
            errs(3, k) = fe_frequency(deck, 1)*2.0_dp*pi/navier_omega11(lmt, deck) - 1.0_dp
         else
            errs(3, k) = 0.0_dp
         end if
         cells(1:8) = [character(len=cw) :: cell(trim(inum(meshes(k))) // ' x ' // trim(inum(meshes(k)))), &
            inum(meshes(k)), &
            sci(errs(1, k)), rate(e_prev(1), errs(1, k), k), sci(errs(2, k)), rate(e_prev(2), errs(2, k), k), &
            sci(errs(3, k)), rate(e_prev(3), errs(3, k), k)]
         if (meshes(k) > 8) cells(7:8) = '-'
         call table_row(cells(1:8))
         write (du, '(i4, 3es14.5)') meshes(k), abs(errs(:, k))
         e_prev = errs(:, k)
      end do meshes_loop
      close (du)
      call table_close()
   end subroutine check_navier

   !> The Navier centre deflection of the deck's load (m); trunc is the
   !> change from the series with half the terms (relative).
   function navier_centre(lmt, deck, mmax, trunc) result(w)
      type(laminate_t), intent(in) :: lmt
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: mmax
      real(dp), intent(out) :: trunc
      real(dp) :: w, w_half
      integer :: load, stat
      character(len=msg_len) :: errmsg
      load = merge(load_uniform, load_sinusoidal, deck%load_kind == 'uniform')
      call navier_fsdt_static(lmt, deck%a, deck%b, load, deck%load_magnitude, mmax, w, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
      call navier_fsdt_static(lmt, deck%a, deck%b, load, deck%load_magnitude, mmax/2, w_half, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
      trunc = abs(w_half/w - 1.0_dp)
   end function navier_centre

   !> Flexural (1,1) circular frequency of the Navier solution (rad/s).
   function navier_omega11(lmt, deck) result(omega)
      type(laminate_t), intent(in) :: lmt
      type(deck_t), intent(in) :: deck
      real(dp) :: omega, om(3)
      integer :: stat
      character(len=msg_len) :: errmsg
      call navier_frequencies(lmt, deck%a, deck%b, 1, 1, om, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
      omega = om(1)
   end function navier_omega11

   ! ================================================================ check 2

   !> NAFEMS FV52: the four lowest frequencies of the thick plate.
   subroutine check_fv52()
      real(dp), parameter :: nafems(4) = [45.897_dp, 109.44_dp, 109.44_dp, 167.89_dp]
      integer, parameter :: meshes(4) = [2, 4, 6, 8]
      !> largest relative difference from the published values on the 8 x 8 mesh
      real(dp), parameter :: tol = 1.0e-3_dp
      integer, parameter :: mn(2, 4) = reshape([1, 1, 1, 2, 2, 1, 2, 2], [2, 4])
      type(deck_t) :: deck0, deck
      type(modal_result_t) :: res
      type(laminate_t) :: lmt
      real(dp) :: f(4), om(3), worst, fprog(8)
      integer :: k, j, stat
      character(len=msg_len) :: errmsg
      character(len=cw) :: cells(7)

      call load_deck('fv52', deck0)
      call table_open('fv52', [character(len=cw) :: 'source', 'f1 (Hz)', 'f2', 'f3', 'f4', &
         'largest difference from NAFEMS', 'w share of the kinetic energy, lowest'])
      call table_row([character(len=cw) :: 'NAFEMS FV52 (published)', num(nafems(1), '(f9.3)'), &
         num(nafems(2), '(f9.2)'), num(nafems(3), '(f9.2)'), num(nafems(4), '(f9.2)'), '-', '-'])
      ! Navier with the deck's k^2 = pi^2/12, and with 5/6 for comparison
      lmt = deck_laminate(deck0)
      do j = 1, 4
         call navier_frequencies(lmt, deck0%a, deck0%b, mn(1, j), mn(2, j), om, stat, errmsg)
         f(j) = om(1)/(2.0_dp*pi)
      end do
      call table_row([character(len=cw) :: 'Navier, Mindlin, k² = π²/12', num(f(1), '(f9.3)'), &
         num(f(2), '(f9.3)'), num(f(3), '(f9.3)'), num(f(4), '(f9.3)'), sci(maxval(abs(f/nafems - 1.0_dp))), '-'])
      deck = deck0
      deck%k4 = sqrt(5.0_dp/6.0_dp);  deck%k5 = deck%k4
      lmt = deck_laminate(deck)
      do j = 1, 4
         call navier_frequencies(lmt, deck%a, deck%b, mn(1, j), mn(2, j), om, stat, errmsg)
         f(j) = om(1)/(2.0_dp*pi)
      end do
      call table_row([character(len=cw) :: 'Navier, Mindlin, k² = 5/6', num(f(1), '(f9.3)'), &
         num(f(2), '(f9.3)'), num(f(3), '(f9.3)'), num(f(4), '(f9.3)'), sci(maxval(abs(f/nafems - 1.0_dp))), '-'])
      worst = 0.0_dp
      meshes_loop: do k = 1, size(meshes)
         deck = deck0
         deck%nx = meshes(k);  deck%ny = meshes(k)
         call fe_modes(deck, 4, res)
         f = res%freq(1:4)
         worst = maxval(abs(f/nafems - 1.0_dp))
         cells = [character(len=cw) :: cell('FE, full ' // trim(inum(meshes(k))) // ' x ' // trim(inum(meshes(k)))), &
            num(f(1), '(f9.3)'), num(f(2), '(f9.3)'), num(f(3), '(f9.3)'), num(f(4), '(f9.3)'), sci(worst), &
            num(minval(res%fraction(1, 1:4)), '(f6.3)')]
         call table_row(cells)
      end do meshes_loop
      call table_close()
      call record('2 NAFEMS FV52', 'four lowest frequencies, FE (full 8 x 8) / NAFEMS - 1', worst, tol)

      ! -- the program path: ./impact on the deck writes the same frequencies
      call run_program('fv52', 'build/validation/fv52_modes.dat', stat)
      if (stat == 0) then
         call read_rows('build/validation/fv52_modes.dat', 6, fprog, 2, stat)
      end if
      call fe_modes(deck0, deck0%mode_count, res)
      worst = 1.0_dp
      if (stat == 0) worst = maxval(abs(fprog(1:min(8, deck0%mode_count))/res%freq(1:min(8, deck0%mode_count)) &
                                        - 1.0_dp))
      call record('program path', './impact validation/decks/fv52.nml against the library', worst, 1.0e-6_dp)
   end subroutine check_fv52

   ! ================================================================ check 3

   !> Shear locking: a/h = 1000 against the classical plate, the paper's
   !> selective rule against full 3 x 3 shear integration.
   subroutine check_locking()
      integer, parameter :: meshes(4) = [1, 2, 4, 8]
      real(dp), parameter :: ratios(4) = [10.0_dp, 100.0_dp, 1000.0_dp, 10000.0_dp]
      !> FE (MITC9 and selective, quarter 4 x 4) / classical plate - 1 at a/h = 1000
      real(dp), parameter :: tol = 1.0e-3_dp
      type(deck_t) :: deck0, deck
      type(laminate_t) :: lmt
      real(dp) :: w_clpt, w_sel, w_full, w_mitc, w_fsdt, trunc, worst, worst_sel
      integer :: k, du
      character(len=cw) :: cells(7)

      call load_deck('locking', deck0)
      lmt = deck_laminate(deck0)
      w_clpt = navier_clpt_centre(lmt, deck0%a, deck0%b, load_uniform, deck0%load_magnitude, mmax_series)
      call table_open('locking_mesh', [character(len=cw) :: 'quarter mesh', &
         'w / w classical, MITC9 (the default)', 'error', &
         'w / w classical, selective 2 x 2 shear (the paper)', 'error', &
         'w / w classical, full 3 x 3 shear', 'error'])
      worst = 0.0_dp;  worst_sel = 0.0_dp
      meshes_loop: do k = 1, size(meshes)
         deck = deck0
         deck%nx = meshes(k);  deck%ny = meshes(k)
         deck%shear_rule = 'mitc9'
         w_mitc = fe_static_centre(deck)
         deck%shear_rule = 'selective'
         w_sel = fe_static_centre(deck)
         deck%shear_rule = 'full'
         w_full = fe_static_centre(deck)
         cells = [character(len=cw) :: cell(trim(inum(meshes(k))) // ' x ' // trim(inum(meshes(k)))), &
            num(w_mitc/w_clpt, '(f10.6)'), sci(w_mitc/w_clpt - 1.0_dp), num(w_sel/w_clpt, '(f10.6)'), &
            sci(w_sel/w_clpt - 1.0_dp), num(w_full/w_clpt, '(es10.3)'), sci(w_full/w_clpt - 1.0_dp)]
         call table_row(cells)
         if (meshes(k) == 4) worst = abs(w_mitc/w_clpt - 1.0_dp)
         if (meshes(k) == 4) worst_sel = abs(w_sel/w_clpt - 1.0_dp)
      end do meshes_loop
      call table_close()
      call record('3 shear locking', 'a/h = 1000: w, FE MITC9 (quarter 4 x 4) / classical - 1', worst, tol)
      call record('3 shear locking', 'a/h = 1000: w, FE selective (quarter 4 x 4) / classical - 1', worst_sel, tol)

      ! -- a central force on the same thin plate: the classical series (the
      !    FSDT's shear part is log-singular under the force but of order
      !    (h/a)^2 log(a/h) ~ 1e-5 at a/h = 1000)
      deck = deck0
      deck%load_kind = 'central_force';  deck%load_magnitude = 1.0_dp
      w_clpt = navier_clpt_centre(lmt, deck%a, deck%b, load_central_force, deck%load_magnitude, mmax_series)
      call table_open('locking_force', [character(len=cw) :: 'quarter mesh', &
         'central force: w / w classical (Navier), MITC9', 'error', 'selective', 'error'])
      force_meshes: do k = 1, size(meshes)
         deck%nx = 2*meshes(k);  deck%ny = deck%nx
         deck%shear_rule = 'mitc9'
         w_mitc = fe_static_centre(deck)
         deck%shear_rule = 'selective'
         w_sel = fe_static_centre(deck)
         call table_row([character(len=cw) :: cell(trim(inum(deck%nx)) // ' x ' // trim(inum(deck%nx))), &
            num(w_mitc/w_clpt, '(f10.6)'), sci(w_mitc/w_clpt - 1.0_dp), &
            num(w_sel/w_clpt, '(f10.6)'), sci(w_sel/w_clpt - 1.0_dp)])
         if (deck%nx == 8) worst = abs(w_mitc/w_clpt - 1.0_dp)
      end do force_meshes
      call table_close()
      call record('3 shear locking', 'a/h = 1000, central force: w, FE MITC9 (quarter 8 x 8) / classical - 1', &
         worst, tol)

      call table_open('locking_thickness', [character(len=cw) :: 'a/h', 'w FE MITC9 / w Navier FSDT', &
         'w FE MITC9 / w classical', 'w FE selective / w classical', 'w Navier FSDT / w classical', &
         'w FE, full 3 x 3 shear / w classical'])
      open (newunit=du, file=out_dir // '/locking.dat', status='replace', action='write')
      write (du, '(a)') '# check 3: isotropic simply supported square plate, uniform load, quarter 4 x 4'
      write (du, '(a)') '# columns: 1 a/h (-), 2 w FE selective / w classical (-), ' // &
         '3 w FE full 3x3 shear / w classical (-), 4 w Navier FSDT / w classical (-), 5 w FE MITC9 / w classical (-)'
      thickness: do k = 1, size(ratios)
         deck = deck0
         deck%h = deck%a/ratios(k)
         lmt = deck_laminate(deck)
         w_clpt = navier_clpt_centre(lmt, deck%a, deck%b, load_uniform, deck%load_magnitude, mmax_series)
         w_fsdt = navier_centre(lmt, deck, mmax_series, trunc)
         deck%shear_rule = 'mitc9'
         w_mitc = fe_static_centre(deck)
         deck%shear_rule = 'selective'
         w_sel = fe_static_centre(deck)
         deck%shear_rule = 'full'
         w_full = fe_static_centre(deck)
         cells(1:6) = [character(len=cw) :: num(ratios(k), '(f8.0)'), num(w_mitc/w_fsdt, '(f10.6)'), &
            num(w_mitc/w_clpt, '(f10.6)'), num(w_sel/w_clpt, '(f10.6)'), num(w_fsdt/w_clpt, '(f10.6)'), &
            num(w_full/w_clpt, '(es10.3)')]
         call table_row(cells(1:6))
         write (du, '(f10.1, 4es14.6)') ratios(k), w_sel/w_clpt, w_full/w_clpt, w_fsdt/w_clpt, w_mitc/w_clpt
      end do thickness
      close (du)
      call table_close()
   end subroutine check_locking

   ! ================================================================ check 4

   !> Nonlinear cylindrical bending of a strip with immovable edges against
   !> Timoshenko & Woinowsky-Krieger Arts. 2-3.
   subroutine check_strip()
      character(len=24), parameter :: decks(2) = [character(len=24) :: 'strip_simply_supported', 'strip_clamped']
      integer, parameter :: edges(2) = [edge_simply_supported, edge_clamped]
      real(dp), parameter :: q_table(9) = [1.0_dp, 2.0_dp, 5.0_dp, 10.0_dp, 20.0_dp, 50.0_dp, 100.0_dp, &
                                           200.0_dp, 400.0_dp]
      integer, parameter :: meshes(4) = [2, 4, 8, 16]
      !> FE (8 elements along the half span) / TWK - 1 over Q = 1..400
      real(dp), parameter :: tol = 1.0e-3_dp
      type(deck_t) :: deck(2), dk
      type(static_result_t) :: res(2), rm
      real(dp) :: qscale(2), w_ref, u, worst, q, err, e_prev(2), wprog(7)
      real(dp), allocatable :: wtwk(:,:)
      integer :: ie, i, k, stat, du, n
      character(len=msg_len) :: errmsg
      character(len=cw) :: cells(7)

      worst = 0.0_dp
      edges_loop: do ie = 1, 2
         call load_deck(decks(ie), deck(ie))
         call fe_static(deck(ie), res(ie))
         qscale(ie) = deck(ie)%a**4/(deck(ie)%e1*deck(ie)%h**4)     ! Q per Pa
      end do edges_loop
      n = res(1)%increments
      allocate (wtwk(2, 0:n))
      wtwk = 0.0_dp
      open (newunit=du, file=out_dir // '/strip.dat', status='replace', action='write')
      write (du, '(a)') '# check 4: strip with immovable edges, w0/h against Q = q l^4/(E h^4), nu = 0.3'
      write (du, '(a)') '# columns: 1 Q (-), 2 w0/h TWK simply supported, 3 FE, 4 w0/h TWK built in, 5 FE, ' // &
         '6 linear simply supported 5 Q 12 (1 - nu^2)/384, 7 linear built in Q 12 (1 - nu^2)/384'
      path: do i = 1, n
         do ie = 1, 2
            q = res(ie)%load_factor(i)*deck(ie)%load_magnitude*qscale(ie)
            call strip_deflection(edges(ie), deck(ie)%nu12, q, wtwk(ie, i), u, stat, errmsg)
            if (stat /= 0) call fail(errmsg)
            err = res(ie)%w_centre(i)/deck(ie)%h/wtwk(ie, i) - 1.0_dp
            worst = max(worst, abs(err))
         end do
         write (du, '(f10.4, 6es14.6)') q, wtwk(1, i), res(1)%w_centre(i)/deck(1)%h, wtwk(2, i), &
            res(2)%w_centre(i)/deck(2)%h, 5.0_dp*q*12.0_dp*(1.0_dp - deck(1)%nu12**2)/384.0_dp, &
            q*12.0_dp*(1.0_dp - deck(1)%nu12**2)/384.0_dp
      end do path
      close (du)

      call table_open('strip', [character(len=cw) :: 'Q = q l⁴/(E h⁴)', 'w0/h simply supported, TWK', 'FE', &
         'error', 'w0/h built in, TWK', 'FE', 'error'])
      rows: do k = 1, size(q_table)
         i = nint(q_table(k)/(deck(1)%load_magnitude*qscale(1))*real(n, dp))
         cells = [character(len=cw) :: num(q_table(k), '(f6.0)'), num(wtwk(1, i), '(f9.5)'), &
            num(res(1)%w_centre(i)/deck(1)%h, '(f9.5)'), sci(res(1)%w_centre(i)/deck(1)%h/wtwk(1, i) - 1.0_dp), &
            num(wtwk(2, i), '(f9.5)'), num(res(2)%w_centre(i)/deck(2)%h, '(f9.5)'), &
            sci(res(2)%w_centre(i)/deck(2)%h/wtwk(2, i) - 1.0_dp)]
         call table_row(cells)
      end do rows
      call table_close()
      call record('4 nonlinear strip', 'w0/h, FE (8 elements per half span) / TWK - 1, Q = 1..400', worst, tol)

      ! -- the error against the mesh at Q = 400
      e_prev = 0.0_dp
      call table_open('strip_mesh', [character(len=cw) :: 'elements per half span', &
         'simply supported: error at Q = 400', 'rate', 'built in: error at Q = 400', 'rate'])
      do k = 1, size(meshes)
         do ie = 1, 2
            dk = deck(ie)
            dk%nx = meshes(k)
            dk%load_increments = 40
            call fe_static(dk, rm)
            q = dk%load_magnitude*qscale(ie)
            call strip_deflection(edges(ie), dk%nu12, q, w_ref, u, stat, errmsg)
            err = rm%w_centre(rm%increments)/dk%h/w_ref - 1.0_dp
            cells(2*ie) = sci(err)
            cells(2*ie + 1) = rate(e_prev(ie), err, k)
            e_prev(ie) = err
         end do
         cells(1) = inum(meshes(k))
         call table_row(cells(1:5))
      end do
      call table_close()

      ! -- the program path: ./impact on the simply supported deck
      call run_program('strip_simply_supported', 'build/validation/strip_simply_supported_static.dat', stat)
      if (stat == 0) call read_last_row('build/validation/strip_simply_supported_static.dat', 7, wprog, stat)
      worst = 1.0_dp
      if (stat == 0) worst = abs(wprog(4)*1.0e-3_dp/res(1)%w_centre(n) - 1.0_dp)
      call record('program path', './impact validation/decks/strip_simply_supported.nml against the library', &
         worst, 1.0e-6_dp)
   end subroutine check_strip

   ! ================================================================ check 5

   !> Step pressure on the simply supported cross-ply plate against the
   !> modal (Navier) solution; time-step convergence.
   subroutine check_transient()
      integer, parameter :: steps_per_period(6) = [10, 20, 40, 80, 160, 320]
      !> the sinusoidal load at T/dt = 320 (error of the rule (omega dt)^2/12 x omega t = 4e-4 at t = 2T)
      real(dp), parameter :: tol_sin = 1.0e-3_dp
      !> the uniform load, quarter 16 x 16, T/dt = 800: 0.1 % of the peak
      real(dp), parameter :: tol_uni = 1.0e-3_dp
      type(deck_t) :: deck0, deck
      type(laminate_t) :: lmt
      type(navier_series_t) :: s
      type(pressure_result_t) :: res
      real(dp) :: period, e_prev, err, wmax, worst, energy_err, eprog(7), worst_energy
      !> the linear theory: the average acceleration rule keeps W = KE + U exactly; rounding only
      real(dp), parameter :: tol_energy = 1.0e-7_dp
      real(dp), allocatable :: wref(:)
      integer :: k, i, du, stat, nstep
      character(len=msg_len) :: errmsg
      character(len=cw) :: cells(5)

      call load_deck('transient', deck0)
      lmt = deck_laminate(deck0)
      period = 2.0_dp*pi/navier_omega11(lmt, deck0)

      ! -- sinusoidal pressure: only the (1,1) terms; dt ladder
      call navier_fsdt(lmt, deck0%a, deck0%b, load_sinusoidal, deck0%load_magnitude, 1, s, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
      call table_open('transient_dt', [character(len=cw) :: 'T11/dt', 'dt (μs)', &
         'max |w FE - w Navier| / max |w Navier|, 0 < t < 2 T11', 'rate', 'energy balance |W - KE - U| / W'])
      open (newunit=du, file=out_dir // '/transient_dt.dat', status='replace', action='write')
      write (du, '(a)') '# check 5: sinusoidal step pressure, error of the centre deflection over 0 < t < 2 T11'
      write (du, '(a)') '# columns: 1 T11/dt (-), 2 dt (us), 3 max error / max |w| (-)'
      e_prev = 0.0_dp
      worst = 0.0_dp
      worst_energy = 0.0_dp
      dt_ladder: do k = 1, size(steps_per_period)
         deck = deck0
         deck%dt = period/steps_per_period(k)
         nstep = 2*steps_per_period(k)
         call fe_pressure(deck, nstep, res)
         allocate (wref(0:nstep))
         do i = 0, nstep
            wref(i) = navier_step_centre(s, res%t(i))
         end do
         wmax = maxval(abs(wref))
         err = maxval(abs(res%w_centre - wref))/wmax
         energy_err = abs(res%work(nstep) - res%kinetic(nstep) - res%strain(nstep))/abs(res%work(nstep))
         worst_energy = max(worst_energy, energy_err)
         cells = [character(len=cw) :: inum(steps_per_period(k)), num(deck%dt*1.0e6_dp, '(f9.3)'), sci(err), &
            rate(e_prev, err, k, 0.5_dp), sci(energy_err)]
         call table_row(cells)
         write (du, '(i6, f12.4, es14.5)') steps_per_period(k), deck%dt*1.0e6_dp, err
         if (k == size(steps_per_period)) worst = err
         if (k == 1 .or. k == size(steps_per_period)) call write_transient_curve(k, res, wref)
         e_prev = err
         deallocate (wref)
      end do dt_ladder
      close (du)
      call table_close()
      call record('5 transient', 'sinusoidal step: max |w FE - w Navier| / max w, T11/dt = 320', worst, tol_sin)
      call record('5 transient', 'linear: energy balance |W - KE - U| / W, every T11/dt', worst_energy, tol_energy)

      ! -- uniform pressure: the Navier series; two meshes, T/dt = 400 and 800
      call navier_fsdt(lmt, deck0%a, deck0%b, load_uniform, deck0%load_magnitude, 199, s, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
      call table_open('transient_uniform', [character(len=cw) :: 'load', 'quarter mesh', 'T11/dt', &
         'max |w FE - w Navier| / max |w Navier|, 0 < t < 2 T11', 'peak w FE / peak w Navier - 1'])
      uniform_runs: do k = 1, 3
         deck = deck0
         deck%load_kind = 'uniform'
         deck%nx = merge(8, 16, k == 1);  deck%ny = deck%nx
         nstep = merge(800, 1600, k < 3)
         deck%dt = 2.0_dp*period/nstep
         call fe_pressure(deck, nstep, res)
         allocate (wref(0:nstep))
         do i = 0, nstep
            wref(i) = navier_step_centre(s, res%t(i))
         end do
         err = maxval(abs(res%w_centre - wref))/maxval(abs(wref))
         call table_row([character(len=cw) :: 'uniform', cell(trim(inum(deck%nx)) // ' x ' // trim(inum(deck%nx))), &
            inum(nstep/2), &
            sci(err), sci(maxval(res%w_centre)/maxval(wref) - 1.0_dp)])
         if (k == 3) call write_transient_curve(0, res, wref)
         deallocate (wref)
      end do uniform_runs
      call table_close()
      call record('5 transient', 'uniform step: max |w FE - w Navier| / max w, quarter 16 x 16, T11/dt = 800', &
         err, tol_uni)

      ! -- the program path: ./impact on the deck (T11/dt as the deck gives it)
      deck = deck0
      nstep = nint(deck%t_end/deck%dt)
      call fe_pressure(deck, nstep, res)
      call run_program('transient', 'build/validation/transient_pressure_history.dat', stat)
      if (stat == 0) call read_last_row('build/validation/transient_pressure_history.dat', 7, eprog, stat)
      err = 1.0_dp
      if (stat == 0) err = abs(eprog(2)*1.0e-3_dp/res%w_centre(nstep) - 1.0_dp)
      call record('program path', './impact validation/decks/transient.nml against the library', err, 1.0e-6_dp)
   end subroutine check_transient

   !> Writes w(t) of FE and Navier for the plot (k = 0: the uniform load).
   subroutine write_transient_curve(k, res, wref)
      integer, intent(in) :: k
      type(pressure_result_t), intent(in) :: res
      real(dp), intent(in) :: wref(0:)
      integer :: du, i
      character(len=8) :: tag
      tag = 'uniform'
      if (k > 0) write (tag, '(a,i0)') 'sin_', k
      open (newunit=du, file=out_dir // '/transient_' // trim(tag) // '.dat', status='replace', action='write')
      write (du, '(a)') '# check 5: centre deflection after a step pressure (' // trim(tag) // ')'
      write (du, '(a)') '# columns: 1 time (ms), 2 w FE (mm), 3 w Navier (mm)'
      do i = 0, res%nstep
         write (du, '(f12.6, 2es16.7)') res%t(i)*1.0e3_dp, res%w_centre(i)*1.0e3_dp, wref(i)*1.0e3_dp
      end do
      close (du)
   end subroutine write_transient_curve

   ! ================================================================ check 6

   !> The impactor on a rigid target: the code's contact kernels alone (law,
   !> eq. 21, eq. 17 with the bracket) against Hertz, and ./impact with a
   !> near-rigid plate.
   subroutine check_hertz()
      integer, parameter :: steps(5) = [25, 50, 100, 200, 400]
      !> relative tolerance of the kernel-level run at t_c/dt = 400
      real(dp), parameter :: tol_kernel = 1.0e-4_dp
      !> ./impact at dt = 0.25 us (t_c/dt ~ 1280; durations to +-dt)
      real(dp), parameter :: tol_program = 2.0e-3_dp
      real(dp), parameter :: mass = 0.243_dp, v0 = 3.0_dp
      character(len=8), parameter :: laws(2) = [character(len=8) :: 'elastic', 'paper']
      !> contact iteration of the kernel-level run: to rounding (eq. 17)
      real(dp), parameter :: cr1_kernel = 1.0e-12_dp
      integer, parameter :: max_iter = 200
      type(contact_law_t) :: law
      type(hertz_impact_t) :: ref
      type(rigid_target_result_t) :: rt
      real(dp) :: got(5), want(5), err(5), e_prev(5), worst, sval(4), amax
      real(dp), allocatable :: hist(:,:)
      integer :: il, k, stat
      character(len=cw) :: cells(7)

      worst = 0.0_dp
      call table_open('hertz_kernel', [character(len=cw) :: 'law', 't_c/dt', 'α_m', 'F_m', &
         'contact duration', 'restitution e', 'permanent α_0'])
      laws_loop: do il = 1, 2
         if (il == 1) then
            law = contact_law_t(k=1.413e9_dp, q=1.5_dp, alpha_p=1.667e-5_dp, beta=0.0_dp)
         else
            law = contact_law_t(k=1.413e9_dp, q=2.5_dp, alpha_p=1.667e-5_dp, beta=0.094_dp)
         end if
         ref = hertz_impact(mass, v0, law%k, law%q, law%alpha_p, law%beta)
         want = [ref%alpha_m, ref%f_m, ref%duration, ref%restitution, ref%alpha_0]
         call table_row([character(len=cw) :: cell(trim(laws(il)) // ': closed form'), '-', &
            cell(trim(num(want(1)*1.0e3_dp, '(f10.6)')) // ' mm'), cell(trim(num(want(2), '(f10.3)')) // ' N'), &
            cell(trim(num(want(3)*1.0e6_dp, '(f10.4)')) // ' μs'), num(want(4), '(f9.6)'), &
            cell(trim(num(want(5)*1.0e3_dp, '(f10.6)')) // ' mm')])
         e_prev = 0.0_dp
         dt_ladder: do k = 1, size(steps)
            rt = rigid_target_impact(mass, v0, law, ref%duration/steps(k), cr1_kernel, max_iter, 100*steps(k))
            if (.not. rt%separated) call fail('rigid target: no separation')
            got = [rt%alpha_m, rt%f_m, rt%duration, rt%restitution, rt%alpha_0]
            err = got/max(abs(want), tiny(1.0_dp)) - 1.0_dp
            if (want(5) == 0.0_dp) err(5) = got(5)/want(1)
            cells = [character(len=cw) :: cell(trim(laws(il)) // ': kernels'), inum(steps(k)), sci(err(1)), sci(err(2)), &
               sci(err(3)), sci(err(4)), sci(err(5))]
            call table_row(cells)
            if (k == size(steps)) worst = max(worst, maxval(abs(err)))
            e_prev = err
         end do dt_ladder
      end do laws_loop
      call table_close()
      call record('6 rigid target', 'kernels: α_m, F_m, duration, e, α_0 / closed form - 1, t_c/dt = 400', &
         worst, tol_kernel)

      ! -- ./impact with a near-rigid plate
      worst = 0.0_dp
      call table_open('hertz_program', [character(len=cw) :: 'law', 'α_m (mm)', 'F_m (N)', &
         'contact duration (μs)', 'rebound velocity (m/s)', 'permanent α_0 (mm)', 'largest error'])
      program_runs: do il = 1, 2
         if (il == 1) then
            law = contact_law_t(k=1.413e9_dp, q=1.5_dp, alpha_p=1.667e-5_dp, beta=0.0_dp)
         else
            law = contact_law_t(k=1.413e9_dp, q=2.5_dp, alpha_p=1.667e-5_dp, beta=0.094_dp)
         end if
         ref = hertz_impact(mass, v0, law%k, law%q, law%alpha_p, law%beta)
         call run_program('rigid_target_' // trim(laws(il)), &
            'build/validation/rigid_target_' // trim(laws(il)) // '_summary.dat', stat)
         if (stat /= 0) then
            call record('6 rigid target', './impact ' // trim(laws(il)) // ' did not run', 1.0_dp, tol_program)
            cycle program_runs
         end if
         call summary_values('build/validation/rigid_target_' // trim(laws(il)) // '_summary.dat', &
            [character(len=32) :: 'peak_force_N', 'contact_duration_us', 'rebound_velocity_m_s', &
             'permanent_indentation_mm'], sval, stat)
         call read_columns('build/validation/rigid_target_' // trim(laws(il)) // '_history.dat', 16, hist, stat)
         amax = maxval(hist(3, :))*1.0e-3_dp
         got = [amax, sval(1), sval(2)*1.0e-6_dp, sval(3)/v0, sval(4)*1.0e-3_dp]
         want = [ref%alpha_m, ref%f_m, ref%duration, ref%restitution, ref%alpha_0]
         err = got/max(abs(want), tiny(1.0_dp)) - 1.0_dp
         if (want(5) == 0.0_dp) err(5) = got(5)/want(1)
         call table_row([character(len=cw) :: cell(trim(laws(il)) // ': closed form'), num(want(1)*1.0e3_dp, '(f10.6)'), &
            num(want(2), '(f10.3)'), num(want(3)*1.0e6_dp, '(f10.3)'), num(want(4)*v0, '(f9.6)'), &
            num(want(5)*1.0e3_dp, '(f10.6)'), '-'])
         call table_row([character(len=cw) :: cell(trim(laws(il)) // ': ./impact'), num(got(1)*1.0e3_dp, '(f10.6)'), &
            num(got(2), '(f10.3)'), num(got(3)*1.0e6_dp, '(f10.3)'), num(got(4)*v0, '(f9.6)'), &
            num(got(5)*1.0e3_dp, '(f10.6)'), sci(maxval(abs(err)))])
         worst = max(worst, maxval(abs(err)))
      end do program_runs
      call table_close()
      call record('6 rigid target', './impact, near-rigid plate: α_m, F_m, duration, e, α_0 / closed form - 1', &
         worst, tol_program)
   end subroutine check_hertz

   ! ================================================================ check 7

   !> The paper's Fig. 5: the quarter plate with D16 = D26 = 0 against the
   !> full plate, linear, 243 g at 3 m/s, each boundary condition. Two
   !> comparisons: the quarter against the full plate with D16 = D26 = 0
   !> (the same model on the mirrored mesh: the code's symmetry lines), and
   !> against the full plate as laid up (the approximation of section 3.1).
   subroutine check_fig5()
      character(len=16), parameter :: edges(3) = [character(len=16) :: 'clamped', 'simply_supported', 'free']
      character(len=16), parameter :: models(3) = [character(len=16) :: 'quarter', 'full_drop', 'full']
      character(len=40), parameter :: labels(3) = [character(len=40) :: 'quarter, D16 = D26 = 0', &
         'full, D16 = D26 = 0', 'full, as laid up']
      !> quarter / full with D16 = D26 = 0 - 1: one discrete model, mirrored
      real(dp), parameter :: tol_mirror = 1.0e-6_dp
      !> quarter / full as laid up - 1, first contact: the approximation of
      !> section 3.1 is exact to first order in D16, D26, so its error is of
      !> order max(D16^2/(D11 D66), D26^2/(D22 D66)), computed below
      real(dp) :: tol_approx
      type(deck_t) :: deck
      type(laminate_t) :: lmt
      real(dp) :: v(5, 3), err(5), worst_mirror, worst_approx
      integer :: ie, im, stat, du, i
      real(dp), allocatable :: hist(:,:)
      character(len=cw) :: cells(7)
      logical :: ok

      worst_mirror = 0.0_dp;  worst_approx = 0.0_dp
      call load_deck('fig5_full_clamped', deck)
      lmt = deck_laminate(deck)
      tol_approx = max(lmt%d(1,3)**2/(lmt%d(1,1)*lmt%d(3,3)), lmt%d(2,3)**2/(lmt%d(2,2)*lmt%d(3,3)))
      call table_open('fig5_coupling', [character(len=cw) :: 'D11 (N m)', 'D22', 'D66', 'D16', 'D26', &
         'D16²/(D11 D66)', 'D26²/(D22 D66)'])
      call table_row([character(len=cw) :: num(lmt%d(1,1), '(f9.3)'), num(lmt%d(2,2), '(f9.3)'), &
         num(lmt%d(3,3), '(f9.3)'), num(lmt%d(1,3), '(f9.3)'), num(lmt%d(2,3), '(f9.3)'), &
         sci(lmt%d(1,3)**2/(lmt%d(1,1)*lmt%d(3,3))), sci(lmt%d(2,3)**2/(lmt%d(2,2)*lmt%d(3,3)))])
      call table_close()
      call table_open('fig5', [character(len=cw) :: 'edges', 'model', 'first contact: peak force (N)', &
         'its time (μs)', 'duration (μs)', 'largest deflection (mm)', 'peak force, all contacts (N)'])
      edges_loop: do ie = 1, 3
         ok = .true.
         models_loop: do im = 1, 3
            call run_program('fig5_' // trim(models(im)) // '_' // trim(edges(ie)), 'build/validation/fig5_' // &
               trim(models(im)) // '_' // trim(edges(ie)) // '_history.dat', stat)
            if (stat == 0) call first_contact('build/validation/fig5_' // trim(models(im)) // '_' // &
               trim(edges(ie)), v(:, im), hist, stat)
            if (stat /= 0) then
               ok = .false.
               exit models_loop
            end if
            ! the force histories for the plot: time (us), force (N), w_plate (mm)
            open (newunit=du, file=out_dir // '/fig5_' // trim(models(im)) // '_' // trim(edges(ie)) // '.dat', &
               status='replace', action='write')
            write (du, '(a)') '# check 7: ' // trim(labels(im)) // ', ' // trim(edges(ie)) // ' edges, linear'
            write (du, '(a)') '# columns: 1 time (us), 2 contact force (N), 3 plate deflection at the centre (mm)'
            do i = 1, size(hist, 2)
               write (du, '(f10.2, es14.6, es14.6)') hist(1, i), hist(2, i), hist(4, i)
            end do
            close (du)
            cells = [character(len=cw) :: edges(ie), labels(im), num(v(1, im), '(f10.2)'), num(v(2, im), '(f9.1)'), &
               num(v(3, im), '(f9.1)'), num(v(4, im), '(f9.4)'), num(v(5, im), '(f10.2)')]
            call table_row(cells)
         end do models_loop
         if (.not. ok) then
            call record('7 Fig. 5', trim(edges(ie)) // ': a run failed', 1.0_dp, tol_mirror)
            cycle edges_loop
         end if
         err = v(:, 1)/v(:, 2) - 1.0_dp
         worst_mirror = max(worst_mirror, maxval(abs(err)))
         cells = [character(len=cw) :: edges(ie), 'quarter / full with D16 = D26 = 0 - 1', sci(err(1)), &
            sci(err(2)), sci(err(3)), sci(err(4)), sci(err(5))]
         call table_row(cells)
         err = v(:, 1)/v(:, 3) - 1.0_dp
         worst_approx = max(worst_approx, maxval(abs(err(1:4))))
         cells = [character(len=cw) :: edges(ie), 'quarter / full as laid up - 1', sci(err(1)), sci(err(2)), &
            sci(err(3)), sci(err(4)), sci(err(5))]
         call table_row(cells)
      end do edges_loop
      call table_close()
      call record('7 Fig. 5', 'quarter / full plate with D16 = D26 = 0 - 1 (all five quantities)', worst_mirror, &
         tol_mirror)
      call record('7 Fig. 5', 'quarter / full plate as laid up - 1, first contact (tolerance: max D_i6²/(D_ii D66))', &
         worst_approx, tol_approx)
   end subroutine check_fig5

   !> From <prefix>_history.dat and _summary.dat: the first contact's peak
   !> force (N), its time (us), its duration (us), the largest plate
   !> deflection during it (mm), and the largest force of the run (N).
   subroutine first_contact(prefix, v, hist, stat)
      character(len=*), intent(in) :: prefix
      real(dp), intent(out) :: v(5)
      real(dp), allocatable, intent(out) :: hist(:,:)
      integer, intent(out) :: stat
      real(dp) :: s(1), t_end
      integer :: i
      v = 0.0_dp
      call read_columns(prefix // '_history.dat', 16, hist, stat)
      if (stat /= 0) return
      call summary_values(prefix // '_summary.dat', [character(len=32) :: 'contact_duration_us'], s, stat)
      if (stat /= 0) return
      v(3) = s(1)
      t_end = hist(1, 1) + s(1) + 2.0_dp*(hist(1, 2) - hist(1, 1))
      if (s(1) < 0.0_dp) t_end = huge(1.0_dp)     ! still in contact at the end
      do i = 1, size(hist, 2)
         if (hist(1, i) > t_end) exit
         if (hist(2, i) > v(1)) then
            v(1) = hist(2, i)
            v(2) = hist(1, i)
         end if
         v(4) = max(v(4), hist(4, i))
      end do
      v(5) = maxval(hist(2, :))
   end subroutine first_contact

   ! ================================================================ check 8

   !> Energy: the balance of an elastic scene closes; with the paper's law
   !> the energy dissipated equals the area of the force-indentation loop.
   subroutine check_energy()
      character(len=40), parameter :: runs(4) = [character(len=40) :: 'energy_elastic_linear', &
         'energy_elastic_nonlinear_dt25', 'energy_elastic_nonlinear_dt125', 'energy_elastic_nonlinear_paper_cr2']
      character(len=64), parameter :: labels(4) = [character(len=64) :: 'linear, dt = 2.5 μs', &
         'von Kármán, dt = 2.5 μs, C_r2 = 1e-14', 'von Kármán, dt = 1.25 μs, C_r2 = 1e-14', &
         'von Kármán, dt = 2.5 μs, the paper''s C_r1 = 2e-3, C_r2 = 1e-7']
      !> elastic linear: the rule keeps the energy exactly; rounding only
      real(dp), parameter :: tol_linear = 1.0e-10_dp
      !> elastic von Karman, dt = 2.5 us: O(dt^2) quadrature of the nonlinear force
      real(dp), parameter :: tol_nonlinear = 1.0e-5_dp
      !> dissipated energy against the loop area, trapezoidal in the written rows
      real(dp), parameter :: tol_loop = 1.0e-3_dp
      real(dp), allocatable :: h(:,:)
      real(dp) :: e0, emax(4), left, loop, closed, diss, alpha_m, alpha_0, f_m, sval(1)
      real(dp), parameter :: k = 1.413e9_dp, q = 2.5_dp
      integer :: ir, stat, n, i, du
      character(len=cw) :: cells(4)

      e0 = 0.5_dp*0.243_dp*3.0_dp**2
      call table_open('energy_elastic', [character(len=cw) :: 'elastic scene (clamped, 243 g at 3 m/s)', &
         'max |energy error| / E0', 'contact energy left after separation / E0', 'ratio to the run above'])
      emax = -1.0_dp
      runs_loop: do ir = 1, size(runs)
         call run_program(trim(runs(ir)), 'build/validation/' // trim(runs(ir)) // '_history.dat', stat)
         if (stat /= 0) then
            call record('8 energy', trim(runs(ir)) // ' did not run', 1.0_dp, tol_linear)
            cycle runs_loop
         end if
         call read_columns('build/validation/' // trim(runs(ir)) // '_history.dat', 16, h, stat)
         n = size(h, 2)
         emax(ir) = maxval(abs(h(13, :)))/e0
         left = h(12, n)/e0
         cells = [character(len=cw) :: labels(ir), sci(emax(ir)), sci(left), '-']
         if (ir == 3 .and. emax(2) > 0.0_dp) cells(4) = trim(num(emax(2)/emax(3), '(f6.2)')) // ' (dt halved)'
         call table_row(cells)
      end do runs_loop
      call table_close()
      call record('8 energy', 'elastic, linear: max |energy error| / E0', emax(1), tol_linear)
      call record('8 energy', 'elastic, von Kármán, dt = 2.5 μs: max |energy error| / E0', emax(2), tol_nonlinear)

      ! -- the paper's law: dissipated energy = loop area
      call run_program('energy_paper', 'build/validation/energy_paper_history.dat', stat)
      if (stat /= 0) then
         call record('8 energy', 'energy_paper did not run', 1.0_dp, tol_loop)
         return
      end if
      call read_columns('build/validation/energy_paper_history.dat', 16, h, stat)
      n = size(h, 2)
      ! dissipated: E0 less what the impactor and the plate hold at the end
      diss = e0 - (h(8, n) + h(9, n) + h(10, n))
      ! the loop: trapezoidal rule over the written (F, alpha) pairs
      loop = 0.0_dp
      do i = 2, n
         loop = loop + 0.5_dp*(h(2, i) + h(2, i - 1))*(h(3, i) - h(3, i - 1))*1.0e-3_dp
      end do
      ! the law's loop in closed form, from alpha_m and alpha_0 of the run
      call summary_values('build/validation/energy_paper_summary.dat', [character(len=32) :: &
         'permanent_indentation_mm'], sval, stat)
      alpha_m = maxval(h(3, :))*1.0e-3_dp
      alpha_0 = sval(1)*1.0e-3_dp
      f_m = k*alpha_m**1.5_dp
      closed = 0.4_dp*k*alpha_m**2.5_dp - f_m*(alpha_m - alpha_0)/(q + 1.0_dp)
      call table_open('energy_loop', [character(len=cw) :: 'quantity (paper law, clamped, von Kármán)', &
         'value (mJ)', 'relative to the loop area'])
      call table_row([character(len=cw) :: 'E0 - (KE impactor + KE plate + U plate) at 3 ms', &
         num(diss*1.0e3_dp, '(f10.5)'), sci(diss/loop - 1.0_dp)])
      call table_row([character(len=cw) :: '∮ F dα, trapezoidal over the history rows', &
         num(loop*1.0e3_dp, '(f10.5)'), '0'])
      call table_row([character(len=cw) :: 'closed form 2/5 k α_m^2.5 - F_m (α_m - α_0)/(q + 1)', &
         num(closed*1.0e3_dp, '(f10.5)'), sci(closed/loop - 1.0_dp)])
      call table_row([character(len=cw) :: 'α_m, α_0 of the run (mm)', cell(trim(num(alpha_m*1.0e3_dp, '(f10.6)')) // ', ' // &
         num(alpha_0*1.0e3_dp, '(f10.6)')), '-'])
      call table_close()
      call record('8 energy', 'paper law, point force: dissipated energy / loop area - 1', abs(diss/loop - 1.0_dp), &
         tol_loop)
      call record('8 energy', 'paper law: closed-form loop / loop area - 1', abs(closed/loop - 1.0_dp), tol_loop)
      call check_energy_hertz()
      open (newunit=du, file=out_dir // '/energy_loop.dat', status='replace', action='write')
      write (du, '(a)') '# check 8: force against indentation, paper law, clamped, von Karman'
      write (du, '(a)') '# columns: 1 indentation (mm), 2 force (N), 3 time (us)'
      do i = 1, n
         write (du, '(es14.6, es14.6, f12.3)') h(3, i), h(2, i), h(1, i)
      end do
      close (du)
   end subroutine check_energy

   !> Check 8 with Hertz's load (the default): the energy the contact takes
   !> (E0 less what the impactor and the plate hold) against the law's loop
   !> area. With the pressure-weighted deflection under the impactor, the
   !> impactor's work is the work on the plate plus the law's int F d alpha
   !> plus the work of the moving contact area, int F dp^T D (the weights of
   !> the mean move as the disc grows and shrinks; zero for the point
   !> force): their difference measures that term, which the model has and
   !> the point force has not. Bound: 1e-3 of E0.
   subroutine check_energy_hertz()
      !> the balance closes as with the point force (check 8, elastic: 1e-5 E0
      !> for von Karman at 2.5 us); the dissipation differs from the loop at the
      !> centre by the pressure's work through the patch's deflection relative
      !> to its centre, bounded by a tenth of the loop (VALIDATION.md, check 8)
      real(dp), parameter :: tol_balance = 1.0e-5_dp, tol_patch = 0.1_dp
      real(dp), allocatable :: h(:,:)
      real(dp) :: e0, diss, loop
      integer :: stat, n, i
      e0 = 0.5_dp*0.243_dp*3.0_dp**2
      call run_program('energy_paper_hertz', 'build/validation/energy_paper_hertz_history.dat', stat)
      if (stat /= 0) then
         call record('8 energy', 'energy_paper_hertz did not run', 1.0_dp, tol_balance)
         return
      end if
      call read_columns('build/validation/energy_paper_hertz_history.dat', 16, h, stat)
      n = size(h, 2)
      diss = e0 - (h(8, n) + h(9, n) + h(10, n))
      loop = 0.0_dp
      do i = 2, n
         loop = loop + 0.5_dp*(h(2, i) + h(2, i - 1))*(h(3, i) - h(3, i - 1))*1.0e-3_dp
      end do
      call table_open('energy_loop_hertz', [character(len=cw) :: 'quantity (paper law, clamped, von Kármán, Hertz load)', &
         'value (mJ)', 'relative to E0'])
      call table_row([character(len=cw) :: 'E0 - (KE impactor + KE plate + U plate) at 3 ms', &
         num(diss*1.0e3_dp, '(f10.5)'), sci(diss/e0)])
      call table_row([character(len=cw) :: '∮ F dα, trapezoidal over the history rows', &
         num(loop*1.0e3_dp, '(f10.5)'), sci(loop/e0)])
      call table_row([character(len=cw) :: 'difference: the work of the moving contact area', &
         num((diss - loop)*1.0e3_dp, '(f10.5)'), sci((diss - loop)/e0)])
      call table_row([character(len=cw) :: 'max |energy error| (history column 13)', &
         num(maxval(abs(h(13, :)))*1.0e3_dp, '(es10.3)'), sci(maxval(abs(h(13, :)))/e0)])
      call table_close()
      call record('8 energy', 'Hertz load: max |energy error| / E0 (history column 13)', &
         maxval(abs(h(13, :)))/e0, tol_balance)
      call record('8 energy', 'Hertz load: |dissipated energy - loop area| / loop area (the patch''s own work)', &
         abs(diss - loop)/loop, tol_patch)
   end subroutine check_energy_hertz

   ! ============================================================ FE runs

   !> Reads validation/decks/<name>.nml.
   subroutine load_deck(name, deck)
      character(len=*), intent(in) :: name
      type(deck_t), intent(out) :: deck
      integer :: stat
      character(len=msg_len) :: errmsg
      call read_deck_file(deck_dir // '/' // trim(name) // '.nml', deck, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
   end subroutine load_deck

   !> The laminate of the deck (eq. 6, 9).
   function deck_laminate(deck) result(lmt)
      type(deck_t), intent(in) :: deck
      type(laminate_t) :: lmt
      lmt = laminate_from_layup(lamina_t(deck%e1, deck%e2, deck%g12, deck%g13, deck%g23, deck%nu12, deck%rho), &
                                deck%angles, deck%h, deck%k4, deck%k5)
   end function deck_laminate

   !> The model of the deck (checked first).
   subroutine model_of(deck, model)
      type(deck_t), intent(inout) :: deck
      type(model_t), intent(out) :: model
      integer :: stat
      character(len=msg_len) :: errmsg
      call validate_deck(deck, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
      call build_model(deck, model, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
   end subroutine model_of

   !> Static analysis of the deck.
   subroutine fe_static(deck_in, res)
      type(deck_t), intent(in) :: deck_in
      type(static_result_t), intent(out) :: res
      type(deck_t) :: deck
      type(model_t) :: model
      real(dp), allocatable :: f(:)
      integer :: stat
      character(len=msg_len) :: errmsg
      deck = deck_in
      deck%analysis_kind = 'static'
      call model_of(deck, model)
      allocate (f(model%msh%neq))
      call assemble_load(deck, model, f, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
      call static_solve(model, f, merge(deck%load_increments, 1, model%nonlinear), res, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
   end subroutine fe_static

   !> Centre deflection of the static analysis of the deck at the full load (m).
   function fe_static_centre(deck) result(w)
      type(deck_t), intent(in) :: deck
      real(dp) :: w
      type(static_result_t) :: res
      call fe_static(deck, res)
      w = res%w_centre(res%increments)
   end function fe_static_centre

   !> The lowest `count` modes of the deck (with the shapes unless shapes is false).
   subroutine fe_modes(deck_in, count, res, shapes)
      type(deck_t), intent(in) :: deck_in
      integer, intent(in) :: count
      type(modal_result_t), intent(out) :: res
      logical, intent(in), optional :: shapes
      logical :: vectors
      type(deck_t) :: deck
      type(model_t) :: model
      integer :: stat
      character(len=msg_len) :: errmsg
      deck = deck_in
      deck%analysis_kind = 'modes'
      call model_of(deck, model)
      vectors = .true.
      if (present(shapes)) vectors = shapes
      call modal_solve(model, count, vectors, res, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
   end subroutine fe_modes

   !> Frequency of mode j of the deck (Hz).
   function fe_frequency(deck, j) result(f)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: j
      real(dp) :: f
      type(modal_result_t) :: res
      call fe_modes(deck, j, res, shapes=.false.)
      f = res%freq(j)
   end function fe_frequency

   !> Transient response of the deck to its load, nstep steps of deck%dt.
   subroutine fe_pressure(deck_in, nstep, res)
      type(deck_t), intent(in) :: deck_in
      integer, intent(in) :: nstep
      type(pressure_result_t), intent(out) :: res
      type(deck_t) :: deck
      type(model_t) :: model
      real(dp), allocatable :: f(:)
      integer :: stat
      character(len=msg_len) :: errmsg
      deck = deck_in
      deck%analysis_kind = 'pressure'
      deck%t_end = deck%dt*real(nstep, dp)*(1.0_dp + 1.0e-9_dp)
      call model_of(deck, model)
      allocate (f(model%msh%neq))
      call assemble_load(deck, model, f, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
      call pressure_solve(model, f, deck%dt, nstep, nstep, res, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
   end subroutine fe_pressure

   ! ================================================================ check 9

   !> The element's transverse shear (src/model/shear_strain.f90): the paper's 2x2
   !> rule, full 3x3, the stabilized blend and MITC9 on (a) the growth of the
   !> static compliance under a point force per mesh halving, against the
   !> log rate of Mindlin's theory itself, ln 2 / (2 pi sqrt(Abar44 Abar55));
   !> (b) the zero eigenvalues of one free element, square and distorted
   !> (exactly the 6 rigid-body modes: 3 in-plane, w, two rotations).
   !> Thin-plate locking is check 3; the patch test is a unit test
   !> (tests/test_element.pf).
   subroutine check_element()
      integer, parameter :: rules(4) = [4, 1, 3, 2]     ! mitc9, selective, full, stabilized
      integer, parameter :: nmesh = 4
      integer, parameter :: mx(nmesh) = [6, 12, 24, 48], my(nmesh) = [4, 8, 16, 32]
      !> MITC9's growth from 24 x 16 to 48 x 32 against the theory's rate
      real(dp), parameter :: tol_rate = 3.0e-2_dp
      type(deck_t) :: deck
      type(laminate_t) :: lmt
      real(dp) :: c(nmesh, 4), rate, ev(45), ke(45, 45), xe(2, nen), corner(2, 4), work(45*64), sq, xi(2)
      type(element_geometry_t) :: geo
      integer :: ir, k, i, info, zeros(2, 4), shape_k
      logical :: ok
      character(len=cw) :: cells(6)
      external :: dsyev

      ! -- (a) the point compliance of the paper's clamped plate, quarter
      call load_deck('point_response_converged_9x6', deck)
      deck%edges = 'clamped'
      deck%analysis_kind = 'static';  deck%load_kind = 'central_force';  deck%load_magnitude = 1.0_dp
      lmt = deck_laminate(deck)
      rate = log(2.0_dp)/(2.0_dp*pi*sqrt(lmt%as(1,1)*lmt%as(2,2)))
      rules_loop: do ir = 1, 4
         deck%shear_rule = shear_rule_names(rules(ir))
         do k = 1, nmesh
            deck%nx = mx(k);  deck%ny = my(k)
            c(k, ir) = fe_static_centre(deck)
         end do
      end do rules_loop
      call table_open('element_compliance', [character(len=cw) :: 'shear rule', &
         'w/P on 6 x 4 (m/N)', 'growth 6 x 4 -> 12 x 8 / theory', 'growth 12 x 8 -> 24 x 16 / theory', &
         'growth 24 x 16 -> 48 x 32 / theory', 'w/P on 48 x 32 (m/N)'])
      do ir = 1, 4
         cells = [character(len=cw) :: cell(shear_rule_names(rules(ir))), sci(c(1, ir)), &
            num((c(2, ir) - c(1, ir))/rate, '(f7.3)'), num((c(3, ir) - c(2, ir))/rate, '(f7.3)'), &
            num((c(4, ir) - c(3, ir))/rate, '(f7.3)'), sci(c(4, ir))]
         call table_row(cells)
      end do
      call table_close()
      call record('9 the element', 'MITC9: compliance growth per halving (24 x 16 -> 48 x 32) / theory''s rate - 1', &
         abs((c(4, 1) - c(3, 1))/rate - 1.0_dp), tol_rate)

      ! -- (b) one free element: its zero eigenvalues
      sq = 0.0167_dp
      do shape_k = 1, 2
         if (shape_k == 1) then
            corner = reshape([0.0_dp, 0.0_dp, sq, 0.0_dp, sq, sq, 0.0_dp, sq], [2, 4])
         else
            corner = reshape([0.0_dp, 0.0_dp, 0.02_dp, 0.001_dp, 0.021_dp, 0.018_dp, -0.002_dp, 0.02_dp], [2, 4])
         end if
         do i = 1, nen
            xi = node_xi(i)
            xe(:, i) = matmul(corner, 0.25_dp*[(1 - xi(1))*(1 - xi(2)), (1 + xi(1))*(1 - xi(2)), &
                                               (1 + xi(1))*(1 + xi(2)), (1 - xi(1))*(1 + xi(2))])
         end do
         do ir = 1, 4
            call element_geometry(xe, shear_rule_t(code=rules(ir), eps=deck%stabilization), geo, ok)
            call element_stiffness(lmt, geo, ke)
            call dsyev('N', 'U', 45, ke, 45, ev, work, size(work), info)
            zeros(shape_k, ir) = count(abs(ev) < 1.0e-12_dp*maxval(abs(ev)))
         end do
      end do
      call table_open('element_zeros', [character(len=cw) :: 'shear rule', 'zero eigenvalues, square element', &
         'zero eigenvalues, distorted element', 'rigid-body modes'])
      do ir = 1, 4
         call table_row([character(len=cw) :: cell(shear_rule_names(rules(ir))), inum(zeros(1, ir)), &
            inum(zeros(2, ir)), '6'])
      end do
      call table_close()
      call record('9 the element', 'MITC9: zero eigenvalues of one element - 6 (square, distorted)', &
         real(abs(zeros(1, 1) - 6) + abs(zeros(2, 1) - 6), dp), 0.5_dp)
   end subroutine check_element

   ! =============================================================== check 10

   !> The dynamic point response: the first contact of the paper's simply
   !> supported plate (linear, 243 g at 3 m/s) on three quarter meshes, with
   !> the converged model (MITC9, Hertz's load) and with the paper's (2x2
   !> shear, point force), against the Navier modal solution of the same
   !> plate, the same law and the same Newmark rule with Hertz's load
   !> (validation/navier_impact_solution.f90), converged in its modes.
   subroutine check_point_response()
      character(len=10), parameter :: models(2) = [character(len=10) :: 'converged', 'paper']
      character(len=6), parameter :: meshes(3) = [character(len=6) :: '9x6', '18x12', '36x24']
      !> the converged model's first contact on 18 x 12 and 36 x 24 against the modal solution
      real(dp), parameter :: tol_peak = 1.0e-2_dp, tol_end = 1.5e-2_dp, tol_mesh = 5.0e-3_dp
      !> modes of the reference: every odd m, n <= mmax (converged to 3e-6 in the peak)
      integer, parameter :: mmax = 1023
      type(deck_t) :: deck
      type(navier_problem_t) :: problem
      type(navier_result_t) :: ref
      real(dp) :: fe(3, 2, 3), worst_peak, worst_end, d_peak, d_end
      real(dp), allocatable :: h(:,:)
      integer :: im, k, stat, du, i
      character(len=msg_len) :: errmsg
      character(len=64) :: name
      character(len=cw) :: cells(7)

      call load_deck('point_response_converged_9x6', deck)
      call navier_problem_from_deck(deck, load_hertz, problem, stat, errmsg)
      if (stat == 0) call navier_impact_run(problem, mmax, ref, stat, errmsg)
      if (stat /= 0) then
         call record('10 point response', 'the modal reference did not run: ' // trim(errmsg), 1.0_dp, tol_peak)
         return
      end if
      open (newunit=du, file=out_dir // '/point_response_modal.dat', status='replace', action='write')
      write (du, '(a)') '# check 10: Navier modal solution, Hertz load; columns: 1 time (us), 2 force (N)'
      do i = 0, ref%nstep
         write (du, '(f10.3, es15.6)') ref%time(i)*1.0e6_dp, ref%force(i)
      end do
      close (du)
      models_loop: do im = 1, 2
         do k = 1, 3
            name = 'point_response_' // trim(models(im)) // '_' // trim(meshes(k))
            call run_program(trim(name), out_dir // '/' // trim(name) // '_summary.dat', stat)
            fe(:, im, k) = -1.0_dp
            if (stat /= 0) cycle
            call read_columns(out_dir // '/' // trim(name) // '_history.dat', 16, h, stat)
            if (stat == 0) fe(:, im, k) = force_pulse(h(1, :)*1.0e-6_dp, h(2, :))
         end do
      end do models_loop

      call table_open('point_response', [character(len=cw) :: 'model', 'quarter mesh', &
         'first-contact peak (N)', 'at (μs)', 'first contact ends (μs)', 'peak / modal - 1', 'end / modal - 1'])
      call table_row([character(len=cw) :: 'Navier modal solution', cell('m, n <= ' // trim(inum(mmax))), &
         num(ref%first_peak_force, '(f9.2)'), num(ref%first_peak_time*1.0e6_dp, '(f8.1)'), &
         num(ref%s%first_contact_end*1.0e6_dp, '(f8.1)'), '0', '0'])
      worst_peak = 0.0_dp;  worst_end = 0.0_dp
      do im = 1, 2
         do k = 1, 3
            d_peak = fe(1, im, k)/ref%first_peak_force - 1.0_dp
            d_end = fe(3, im, k)/ref%s%first_contact_end - 1.0_dp
            cells = [character(len=cw) :: cell(merge('converged: MITC9, Hertz load', 'the paper''s: 2x2, point     ', &
               im == 1)), cell(meshes(k)), num(fe(1, im, k), '(f9.2)'), num(fe(2, im, k)*1.0e6_dp, '(f8.1)'), &
               num(fe(3, im, k)*1.0e6_dp, '(f8.1)'), sci(d_peak), sci(d_end)]
            if (fe(3, im, k) < 0.0_dp) cells([5, 7]) = [character(len=cw) :: 'does not end', '–']
            call table_row(cells)
            if (im == 1 .and. k >= 2) then
               worst_peak = max(worst_peak, abs(d_peak))
               worst_end = max(worst_end, abs(d_end))
            end if
         end do
      end do
      call table_close()
      call record('10 point response', 'converged model, 18 x 12 and 36 x 24: first-contact peak / modal - 1', &
         worst_peak, tol_peak)
      call record('10 point response', 'converged model, 18 x 12 and 36 x 24: first-contact end / modal - 1', &
         worst_end, tol_end)
      call record('10 point response', 'converged model: 18 x 12 / 36 x 24 - 1, peak and end of the first contact', &
         max(abs(fe(1, 1, 2)/fe(1, 1, 3) - 1.0_dp), abs(fe(3, 1, 2)/fe(3, 1, 3) - 1.0_dp)), tol_mesh)

   end subroutine check_point_response

   !> The first contact of a force history: its peak, the time of the
   !> peak and the time the force returns to 0 (-1 when it does not).
   function force_pulse(t, f) result(v)
      real(dp), intent(in) :: t(:), f(:)
      real(dp) :: v(3)
      integer :: j
      logical :: started
      v = [0.0_dp, 0.0_dp, -1.0_dp]
      started = .false.
      do j = 1, size(f)
         if (f(j) > 0.0_dp) started = .true.
         if (.not. started) cycle
         if (f(j) <= 0.0_dp) then
            v(3) = t(j)
            return
         end if
         if (f(j) > v(1)) v(1:2) = [f(j), t(j)]
      end do
   end function force_pulse

   ! =============================================================== check 11

   !> Ply stresses (src/strength/ply_stress.f90) of a linear static solution at every
   !> 3 x 3 Gauss point and ply face, against (a) the Navier solution of the
   !> simply supported cross-ply [0/90/90/0] under the sinusoidal load, a/h =
   !> 10 (reference_solutions item 5: exact in-plane stresses, transverse
   !> shear from equilibrium), and (b) a homogeneous isotropic plate against
   !> the plate formulas (item 6), on quarter meshes 4 x 4 to 32 x 32; then
   !> (c) each criterion on single stress states against hand values.
   !> Error of a component: the largest |FE - exact| over the points and
   !> faces, over the largest |exact| of that component.
   subroutine check_ply_stresses()
      integer, parameter :: meshes(4) = [4, 8, 16, 32]
      !> in-plane: first derivatives at the 3 x 3 points, second order in the
      !> element size (1.0e-4 measured at 32 x 32: twice that); shear: the
      !> second derivatives of a biquadratic field, first order (1.8e-2
      !> measured at 32 x 32: the next 40 %); the observed order of the shear
      !> from 16 x 16 to 32 x 32 must be 1 within 0.1, that of the in-plane
      !> stresses 2 within 0.1
      real(dp), parameter :: tol_inplane = 2.0e-4_dp, tol_shear = 2.5e-2_dp, tol_order = 0.1_dp
      !> the criteria: rounding only
      real(dp), parameter :: tol_criteria = 1.0e-12_dp
      real(dp) :: err(5, size(meshes), 2), e_prev(5)
      integer :: k, c, plate, du
      character(len=cw) :: cells(12)

      open (newunit=du, file=out_dir // '/ply_stress_mesh.dat', status='replace', action='write')
      write (du, '(a)') '# check 11: ply stresses, largest |FE - exact|/max|exact| per component, quarter n x n mesh'
      write (du, '(a)') '# columns: 1 n, 2-6 cross-ply s11 s22 t12 t23 t13, 7-11 isotropic s11 s22 t12 t23 t13'
      do k = 1, size(meshes)
         call ply_stress_errors(meshes(k), err(:, k, 1), err(:, k, 2))
         write (du, '(i4, 10es14.5)') meshes(k), err(:, k, 1), err(:, k, 2)
      end do
      close (du)
      do plate = 1, 2
         call table_open(trim(merge('ply_stress_navier   ', 'ply_stress_isotropic', plate == 1)), &
            [character(len=cw) :: 'quarter mesh', 's11 error', 'rate', 's22 error', 'rate', 't12 error', 'rate', &
            't23 error', 'rate', 't13 error', 'rate'])
         e_prev = 0.0_dp
         do k = 1, size(meshes)
            cells(1) = cell(trim(inum(meshes(k))) // ' x ' // trim(inum(meshes(k))))
            do c = 1, 5
               cells(2*c) = sci(err(c, k, plate))
               cells(2*c + 1) = rate(e_prev(c), err(c, k, plate), k)
            end do
            call table_row(cells(1:11))
            e_prev = err(:, k, plate)
         end do
         call table_close()
      end do
      k = size(meshes)
      call record('11 ply stresses', 'cross-ply, Navier: in-plane s11, s22, t12 (32 x 32)', maxval(err(1:3, k, 1)), &
                  tol_inplane)
      call record('11 ply stresses', 'cross-ply, Navier: equilibrium t23, t13 (32 x 32)', maxval(err(4:5, k, 1)), &
                  tol_shear)
      call record('11 ply stresses', 'isotropic plate formulas: in-plane (32 x 32)', maxval(err(1:3, k, 2)), &
                  tol_inplane)
      call record('11 ply stresses', 'isotropic plate formulas: parabolic shear (32 x 32)', maxval(err(4:5, k, 2)), &
                  tol_shear)
      call record('11 ply stresses', 'observed order 16 x 16 -> 32 x 32 of the in-plane stresses - 2', &
                  maxval(abs(log(err(1:3, k - 1, :)/err(1:3, k, :))/log(2.0_dp) - 2.0_dp)), tol_order)
      call record('11 ply stresses', 'observed order 16 x 16 -> 32 x 32 of the equilibrium shear - 1', &
                  maxval(abs(log(err(4:5, k - 1, :)/err(4:5, k, :))/log(2.0_dp) - 1.0_dp)), tol_order)
      call check_criteria(tol_criteria)
   end subroutine check_ply_stresses

   !> The errors of the cross-ply (Navier) and the isotropic plate on the
   !> quarter n x n mesh (check_ply_stresses).
   subroutine ply_stress_errors(n, err_navier, err_iso)
      integer, intent(in) :: n
      real(dp), intent(out) :: err_navier(5), err_iso(5)
      type(deck_t) :: deck
      real(dp), parameter :: e_iso = 70.0e9_dp, nu_iso = 0.3_dp
      integer :: plate
      do plate = 1, 2
         call load_deck('navier_crossply', deck)
         deck%h = deck%a/10.0_dp
         deck%nx = n;  deck%ny = n
         deck%load_kind = 'sinusoidal'
         if (plate == 2) then
            deck%e1 = e_iso;  deck%e2 = e_iso;  deck%nu12 = nu_iso
            deck%g12 = e_iso/(2.0_dp*(1.0_dp + nu_iso));  deck%g13 = deck%g12;  deck%g23 = deck%g12
            deck%angles = [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]
            call errors_of(deck, err_iso, .true.)
         else
            call errors_of(deck, err_navier, .false.)
         end if
      end do
   end subroutine ply_stress_errors

   !> The ply-stress errors of one plate deck (ply_stress_errors).
   subroutine errors_of(deck, err, isotropic)
      type(deck_t), intent(inout) :: deck
      real(dp), intent(out) :: err(5)
      logical, intent(in) :: isotropic
      type(static_result_t) :: res
      type(damage_t) :: dmg
      type(model_t) :: model
      real(dp), allocatable :: sig(:,:,:,:), fi(:,:,:), ref(:,:,:,:), xy(:,:)
      real(dp) :: z
      integer :: np, nply, p, k, f, stat
      character(len=msg_len) :: errmsg
      call fe_static(deck, res)
      deck%analysis_kind = 'static'
      call model_of(deck, model)
      ! the stresses of src/strength/ply_stress.f90 through the run's record (strengths only so it is active)
      deck%xt = 1.0_dp;  deck%xc = 1.0_dp;  deck%yt = 1.0_dp;  deck%yc = 1.0_dp;  deck%s12 = 1.0_dp
      deck%s23 = 1.0_dp
      call damage_open(dmg, deck, model)
      nply = size(deck%angles)
      allocate (xy, source=damage_points(model))
      np = size(xy, 2)
      allocate (sig(5, 2, nply, np), fi(2, nply, np), ref(5, 2, nply, np))
      call damage_stresses(dmg, model, res%d, sig, fi)
      points: do p = 1, np
         if (isotropic) then
            do k = 1, nply
               do f = 1, 2
                  z = -0.5_dp*deck%h + real(k - 2 + f, dp)*deck%h/real(nply, dp)
                  ref(:, f, k, p) = isotropic_sinusoidal_stresses(deck%e1, deck%nu12, deck%h, deck%a, deck%b, &
                     deck%load_magnitude, xy(1, p) + 0.5_dp*deck%a, xy(2, p) + 0.5_dp*deck%b, z)
               end do
            end do
         else
            call navier_sinusoidal_ply_stresses(lamina_t(deck%e1, deck%e2, deck%g12, deck%g13, deck%g23, &
               deck%nu12, deck%rho), deck%angles, model%lmt, deck%a, deck%b, deck%load_magnitude, &
               xy(1, p) + 0.5_dp*deck%a, xy(2, p) + 0.5_dp*deck%b, ref(:, :, :, p), stat, errmsg)
            if (stat /= 0) call fail(errmsg)
         end if
      end do points
      do k = 1, 5
         err(k) = maxval(abs(sig(k, :, :, :) - ref(k, :, :, :)))/maxval(abs(ref(k, :, :, :)))
      end do
   end subroutine errors_of

   !> Each criterion on single stress states against values worked out by
   !> hand (strengths Xt 1000, Xc 800, Yt 50, Yc 200, S12 80, S23 50 MPa).
   subroutine check_criteria(tol)
      real(dp), intent(in) :: tol
      real(dp), parameter :: mpa = 1.0e6_dp
      type(strength_t), parameter :: hand = strength_t(1000.0_dp*mpa, 800.0_dp*mpa, 50.0_dp*mpa, 200.0_dp*mpa, &
         80.0_dp*mpa, 50.0_dp*mpa)
      integer, parameter :: nstate = 9
      !> criterion, stress state (MPa), hand value, and how it was worked out
      integer, parameter :: crit(nstate) = [criterion_hashin, criterion_hashin, criterion_hashin, criterion_hashin, &
         criterion_hashin, criterion_max_stress, criterion_max_stress, criterion_tsai_wu, criterion_tsai_wu]
      real(dp), parameter :: states(5, nstate) = reshape([ &
         500.0_dp, 0.0_dp, 40.0_dp, 0.0_dp, 0.0_dp, &
         -800.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
         0.0_dp, 25.0_dp, 40.0_dp, 25.0_dp, 40.0_dp, &
         0.0_dp, -200.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
         0.0_dp, -150.0_dp, 0.0_dp, 20.0_dp, 0.0_dp, &
         -400.0_dp, 10.0_dp, 40.0_dp, 0.0_dp, 60.0_dp, &
         0.0_dp, -150.0_dp, 0.0_dp, 30.0_dp, 0.0_dp, &
         500.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
         0.0_dp, -200.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], [5, nstate])
      real(dp), parameter :: hand_value(nstate) = [0.5_dp, 1.0_dp, 1.0_dp, 1.0_dp, 0.16_dp, 0.75_dp, 0.75_dp, &
         0.5_dp, 1.0_dp]
      character(len=64), parameter :: how(nstate) = [character(len=64) :: '(500/1000)^2 + 40^2/80^2', &
         '(-800/800)^2', '(25/50)^2 + (25/50)^2 + (40^2 + 40^2)/80^2', 'at -Yc: 1 (eq. 26)', &
         '(150/100)^2 - 3 (150/200) + (20/50)^2', 'max(400/800, 10/50, 60/80)', 'max(150/200, 30/50)', &
         'a = 0.3125, b = -0.125: (b + sqrt(b^2 + 4a))/2', 'at -Yc: 1']
      character(len=12), parameter :: names(3) = [character(len=12) :: 'hashin', 'max_stress', 'tsai_wu']
      real(dp) :: fi, worst
      integer :: j, mode
      character(len=cw) :: cells(6)
      worst = 0.0_dp
      call table_open('criteria', [character(len=cw) :: 'criterion', 'stress state (s11, s22, t12, t23, t13), MPa', &
         'by hand', 'computed', 'mode', 'error'])
      do j = 1, nstate
         call failure_index(hand, crit(j), states(:, j)*mpa, fi, mode)
         worst = max(worst, abs(fi - hand_value(j)))
         cells = [character(len=cw) :: names(crit(j)), cell(trim(num(states(1, j), '(f7.1)')) // ', ' // &
            trim(num(states(2, j), '(f7.1)')) // ', ' // trim(num(states(3, j), '(f6.1)')) // ', ' // &
            trim(num(states(4, j), '(f6.1)')) // ', ' // trim(num(states(5, j), '(f6.1)'))), &
            cell(trim(num(hand_value(j), '(f6.3)')) // ' = ' // trim(how(j))), num(fi, '(f18.15)'), &
            mode_names(mode), sci(fi - hand_value(j))]
         call table_row(cells)
      end do
      call table_close()
      call record('11 failure criteria', 'Hashin, max stress, Tsai-Wu against hand values', worst, tol)
   end subroutine check_criteria

   ! ============================================================ the program

   !> Runs ./impact on validation/decks/<name>.nml (output in build/validation,
   !> terminal in <name>.log); stat = 0 when it exits 0 and `result` exists.
   subroutine run_program(name, result, stat)
      character(len=*), intent(in) :: name, result
      integer, intent(out) :: stat
      integer :: ex, cs, length, st, pid, ended
      logical :: there
      character(len=msg_len) :: exe, why
      ! the program: ./impact, or $IMPACT_EXE when it is set
      call get_environment_variable('IMPACT_EXE', exe, length, st)
      if (st /= 0 .or. length == 0) exe = './impact'
      ! --overwrite: build/validation holds this check's own earlier results;
      ! started without a shell (posix_spawn), its output in <name>.log
      why = ''
      call spawn_program(trim(exe), [character(len=msg_len) :: '--overwrite', deck_dir // '/' // trim(name) // '.nml'], &
                         out_dir // '/' // trim(name) // '.log', pid, cs, why)
      ex = 1
      if (cs == 0) then
         do
            call wait_child(ended, ex)
            if (ended == pid .or. ended < 0) exit
         end do
      end if
      inquire (file=result, exist=there)
      stat = 0
      if (ex /= 0 .or. cs /= 0 .or. .not. there) then
         stat = 1
         if (cs /= 0) then
            write (error_unit, '(a)') 'validate: ' // trim(why)
         else
            write (error_unit, '(a)') 'validate: ./impact ' // deck_dir // '/' // trim(name) // '.nml failed; see ' // &
               out_dir // '/' // trim(name) // '.log'
         end if
      end if
   end subroutine run_program

   !> Column `col` of every numeric row, at most size(values) of them.
   subroutine read_rows(path, ncol, values, col, stat)
      character(len=*), intent(in) :: path
      integer, intent(in) :: ncol, col
      real(dp), intent(out) :: values(:)
      integer, intent(out) :: stat
      real(dp), allocatable :: t(:,:)
      integer :: n
      values = 0.0_dp
      call read_columns(path, ncol, t, stat)
      if (stat /= 0) return
      n = min(size(values), size(t, 2))
      values(:n) = t(col, :n)
   end subroutine read_rows

   !> The last numeric row of a column file.
   subroutine read_last_row(path, ncol, values, stat)
      character(len=*), intent(in) :: path
      integer, intent(in) :: ncol
      real(dp), intent(out) :: values(ncol)
      integer, intent(out) :: stat
      real(dp), allocatable :: t(:,:)
      call read_columns(path, ncol, t, stat)
      values = 0.0_dp
      if (stat == 0 .and. size(t, 2) > 0) values = t(:, size(t, 2))
      if (size(t, 2) == 0) stat = 1
   end subroutine read_last_row

   !> The values of `key = value` lines of a summary file (huge when absent).
   subroutine summary_values(path, keys, values, stat)
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: keys(:)
      real(dp), intent(out) :: values(:)
      integer, intent(out) :: stat
      type(summary_t) :: s
      character(len=msg_len) :: errmsg
      integer :: k
      call read_summary(path, s, stat, errmsg)
      values = [(summary_value(s, trim(keys(k)), huge(1.0_dp)), k = 1, size(keys))]
      if (stat == 0) stat = merge(0, 1, all(values /= huge(1.0_dp)))
   end subroutine summary_values

   ! ============================================================ report

   !> Opens build/validation/<name>.md with its header row.
   subroutine table_open(name, head)
      character(len=*), intent(in) :: name
      character(len=*), intent(in) :: head(:)
      integer :: c
      open (newunit=tu, file=out_dir // '/' // name // '.md', status='replace', action='write')
      call table_row(head)
      write (tu, '(a)', advance='no') '|'
      do c = 1, size(head)
         write (tu, '(a)', advance='no') '---|'
      end do
      write (tu, '(a)') ''
   end subroutine table_open

   subroutine table_row(cells)
      character(len=*), intent(in) :: cells(:)
      integer :: c
      write (tu, '(a)', advance='no') '|'
      do c = 1, size(cells)
         write (tu, '(a)', advance='no') ' ' // md(trim(cells(c))) // ' |'
      end do
      write (tu, '(a)') ''
   end subroutine table_row

   !> Text for a markdown table cell: '|' escaped.
   function md(text) result(s)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: s
      integer :: i
      s = ''
      do i = 1, len(text)
         if (text(i:i) == '|') then
            s = s // '\|'
         else
            s = s // text(i:i)
         end if
      end do
   end function md

   subroutine table_close()
      close (tu)
   end subroutine table_close

   !> A row of the summary table: pass when worst <= tol.
   subroutine record(check, quantity, worst, tol)
      character(len=*), intent(in) :: check, quantity
      real(dp), intent(in) :: worst, tol
      character(len=12) :: verdict
      if (abs(worst) <= tol) then
         npass = npass + 1
         verdict = 'pass'
      else
         nfail = nfail + 1
         verdict = '**FAIL**'
      end if
      write (su, '(a)') '| ' // check // ' | ' // md(quantity) // ' | ' // trim(sci(abs(worst))) // ' | ' // trim(sci(tol)) // &
         ' | ' // trim(verdict) // ' |'
      write (output_unit, '(a)') trim(verdict) // ': ' // check // ': ' // quantity // ': ' // trim(sci(abs(worst))) // &
         ' (tolerance ' // trim(sci(tol)) // ')'
      flush (output_unit)
   end subroutine record

   !> The report's path: the first argument of the command, else default_report.
   function report_path() result(path)
      character(len=:), allocatable :: path
      integer :: length, st
      if (command_argument_count() < 1) then
         path = default_report
         return
      end if
      call get_command_argument(1, length=length, status=st)
      if (st /= 0 .or. length == 0) call fail('usage: validate [REPORT]')
      allocate (character(len=length) :: path)
      call get_command_argument(1, path)
   end function report_path

   !> The directory of a path ('.' when it has none).
   function report_dir(path) result(dir)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: dir
      integer :: k
      k = index(path, '/', back=.true.)
      if (k == 0) then
         dir = '.'
      else
         dir = path(:max(k - 1, 1))
      end if
   end function report_dir

   !> The report: the template copied line by line; make validate fills its
   !> blocks with the tables afterwards (tools/impact_files.py fill).
   subroutine copy_template()
      character(len=4096) :: line
      integer :: ui, uo, ios
      open (newunit=ui, file=template, status='old', action='read', iostat=ios)
      if (ios /= 0) call fail('cannot read ' // template)
      open (newunit=uo, file=report, status='replace', action='write', iostat=ios)
      if (ios /= 0) call fail('cannot write ' // report)
      do
         read (ui, '(a)', iostat=ios) line
         if (ios /= 0) exit
         write (uo, '(a)') trim(line)
      end do
      close (ui)
      close (uo)
   end subroutine copy_template

   ! ============================================================ text

   !> x written with format f, left-adjusted. (The text functions return a
   !> fixed length: gfortran 12 miscounts deferred-length function results
   !> inside array constructors with a type spec.)
   function num(x, f) result(s)
      real(dp), intent(in) :: x
      character(len=*), intent(in) :: f
      character(len=cw) :: s
      write (s, f) x
      s = adjustl(s)
   end function num

   !> A table cell: text padded to the cell width.
   function cell(text) result(s)
      character(len=*), intent(in) :: text
      character(len=cw) :: s
      s = text
   end function cell

   !> A relative error, signed, two digits: '-1.2e-05'.
   function sci(x) result(s)
      real(dp), intent(in) :: x
      character(len=cw) :: s
      if (x == 0.0_dp) then
         s = '0'
         return
      end if
      write (s, '(es9.2e2)') x
      s = adjustl(s)
   end function sci

   !> An integer without blanks.
   function inum(i) result(s)
      integer, intent(in) :: i
      character(len=cw) :: s
      write (s, '(i0)') i
   end function inum

   !> Observed order log(e_prev/e)/log(refinement) ('-' for the first row).
   function rate(e_prev, e, k, refine) result(s)
      real(dp), intent(in) :: e_prev, e
      integer, intent(in) :: k
      real(dp), intent(in), optional :: refine
      character(len=cw) :: s
      real(dp) :: r
      r = 2.0_dp
      if (present(refine)) r = 1.0_dp/refine
      if (k == 1 .or. e == 0.0_dp .or. e_prev == 0.0_dp) then
         s = '-'
      else
         s = num(log(abs(e_prev/e))/log(r), '(f6.2)')
      end if
   end function rate

   !> Prints the cpu time of this program since the last call (the ./impact
   !> runs are other processes) and the wall time.
   subroutine lap(what)
      character(len=*), intent(in) :: what
      real(dp) :: now
      integer(int64) :: count
      call cpu_time(now)
      call system_clock(count)
      write (output_unit, '(a,f8.1,a,f8.1,a)') 'validate: ' // what // ' done: cpu ', now - cpu_last, &
         ' s, wall since start ', real(count - wall0, dp)/real(clock_rate, dp), ' s'
      flush (output_unit)
      cpu_last = now
   end subroutine lap

   !> Stops the validation on a set-up error (not a failed check).
   subroutine fail(message)
      character(len=*), intent(in) :: message
      write (error_unit, '(a)') 'validate: error: ' // trim(message)
      error stop 2
   end subroutine fail

end program validate
