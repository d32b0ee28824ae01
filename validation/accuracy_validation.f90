!> accuracy_validation: the error bars of `impact --accuracy` against the
!> true errors, on scenes that span the field (docs/VALIDATION.md, check 12).
!>
!> Usage (from the repository root, after `make impact navier-impact`):
!>     make validate          (or: build/accuracy_validation)
!>
!> For each scene of validation/decks/accuracy/ (the table `scenes`):
!>  1. ./impact --accuracy TOL on its deck (one scene at a time: each uses
!>     every CPU for its ladder); its summary gives the run chosen (dt_c,
!>     nx_c x ny_c), each result q and its estimated error E, with the time
!>     part E_dt and the mesh part E_mesh.
!>  2. The references, much finer in one direction each, all scenes' runs
!>     at the same time on the CPUs the process may use:
!>       time: the chosen mesh (its grading too) at dt_c/2 and dt_c/4 (Newmark's error of
!>             dt_c/4 is 1/16 of the chosen run's);
!>       mesh: at dt_c, a graded mesh whose element at the impact point is
!>             3/4 of the Hertz contact radius a at the chosen run's peak
!>             force (the disc resolved; its largest element 1/10 of the
!>             quarter's side), and the same family refined 1.5 times;
!>       and, for a simply supported linear scene, the Navier modal
!>       solution (validation/navier_impact.f90: exact in space, the same
!>       Newmark rule) at dt_c/4 and dt_c/8; and one plain run of the deck
!>       (the unit of the price).
!>  3. The true error of q: its time part q - q(dt_c/4) on its mesh plus
!>     its mesh part q - q(finer graded mesh) at its step; with the Navier
!>     solution, q - q_Navier(dt_c/8) directly. The reference's own
!>     uncertainty u: the change between the two time references plus that
!>     between the two mesh references (for Navier: between its two steps).
!>     The bound holds when E >= |true| - u; the table gives E/|true|, how
!>     pessimistic the bound is.
!> Writes build/validation/accuracy_scenes.md, accuracy_bounds.md (the
!> tables of docs/VALIDATION.md), accuracy_bounds.dat (the plot's data,
!> validation/accuracy_plots.gp); exit status 1 when a bound fails.
program accuracy_validation
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use kinds, only: dp, msg_len
   use input_deck, only: deck_t, read_deck_file
   use number_text, only: real_short, int_str
   use result_reader, only: summary_t, read_summary, summary_value, summary_index
   use child_process, only: spawn_program, wait_child, usable_cpus
   use file_system, only: make_directories
   implicit none

   !> One scene: its deck validation/decks/accuracy/<name>.nml, the
   !> accuracy asked for, whether the Navier solution applies.
   type :: scene_t
      character(len=32) :: name = ''
      real(dp) :: tol = 0.01_dp
      logical :: navier = .false.
   end type scene_t

   !> A run: the program, its arguments, its log; its process and state.
   type :: job_t
      character(len=64) :: name = ''
      character(len=:), allocatable :: exe
      character(len=4096), allocatable :: args(:)
      integer :: pid = -1, exit_code = -1
      logical :: done = .false.
      real(dp) :: weight = 1.0_dp           !< expected cost, for the order of starting
   end type job_t

   character(len=*), parameter :: deck_dir = 'validation/decks/accuracy/'
   character(len=*), parameter :: out_dir = 'build/validation/accuracy/'
   character(len=*), parameter :: md_dir = 'build/validation/'
   !> The results compared (their units in their keys).
   integer, parameter :: nq = 5
   character(len=*), parameter :: keys(nq) = [character(len=19) :: 'peak_force_N', 'max_deflection_mm', &
      'contact_duration_us', 'time_of_peak_us', 'max_strain_y_back']
   !> The Navier solution has these (not the strain).
   logical, parameter :: navier_has(nq) = [.true., .true., .true., .true., .false.]
   !> The mesh reference: its element at the impact point over the
   !> contact radius, its largest element over the quarter's side, the
   !> refinement of the second.
   real(dp), parameter :: first_over_radius = 0.75_dp, largest_over_side = 0.1_dp, ref_factor = 1.5_dp

   type(scene_t), parameter :: scenes(10) = [ &
      scene_t('light_fast_clamped', 0.01_dp, .false.), &
      scene_t('light_ss_crossply', 0.01_dp, .true.), &
      scene_t('light_ss_thick', 0.01_dp, .true.), &
      scene_t('mid_ss_angleply', 0.01_dp, .true.), &
      scene_t('mid_thin_clamped', 0.01_dp, .false.), &
      scene_t('paper_clamped', 0.01_dp, .false.), &
      scene_t('paper_ss_linear', 0.01_dp, .true.), &
      scene_t('thick_clamped_angleply', 0.01_dp, .false.), &
      scene_t('heavy_slow_thick', 0.01_dp, .false.), &
      scene_t('heavy_thin_ss', 0.01_dp, .false.)]

   type(summary_t) :: acc(size(scenes))
   type(job_t), allocatable :: jobs(:)
   character(len=:), allocatable :: exe, navier_exe
   character(len=msg_len) :: errmsg
   integer :: is, stat, nfail

   exe = program_or('IMPACT_EXE', './impact')
   navier_exe = program_or('NAVIER_EXE', 'build/navier_impact')
   call make_directories(out_dir, stat, errmsg)
   if (stat /= 0) call fail(errmsg)
   ! -- 1. the accuracy runs, one scene at a time
   do is = 1, size(scenes)
      call accuracy_run(scenes(is), acc(is), stat)
      if (stat /= 0) call fail('the accuracy run of ' // trim(scenes(is)%name) // ' failed: see ' // out_dir // &
                               trim(scenes(is)%name) // '.log')
   end do
   ! -- 2. the references of every scene, together
   allocate (jobs(0))
   do is = 1, size(scenes)
      call plan_references(scenes(is), acc(is), jobs)
   end do
   call run_jobs(jobs, stat, errmsg)
   if (stat /= 0) call fail(errmsg)
   if (any(jobs%exit_code /= 0)) call fail('a reference run failed: ' // trim(jobs(findloc(jobs%exit_code /= 0, &
                                           .true., dim=1))%name) // ' (see its .log in ' // out_dir // ')')
   ! -- 3. the tables
   call write_tables(nfail)
   write (output_unit, '(a)') 'accuracy_validation: ' // int_str(nfail) // ' bound(s) failed; tables: ' // md_dir // &
      'accuracy_bounds.md, ' // md_dir // 'accuracy_scenes.md'
   if (nfail > 0) error stop 1

contains

   !> The program the environment variable names, else the default.
   function program_or(variable, default) result(path)
      character(len=*), intent(in) :: variable, default
      character(len=:), allocatable :: path
      character(len=4096) :: value
      integer :: length, st
      call get_environment_variable(variable, value, length, st)
      path = default
      if (st == 0 .and. length > 0) path = trim(value)
   end function program_or

   !> ./impact --overwrite --accuracy TOL on the scene's deck; its summary.
   subroutine accuracy_run(scene, s, stat)
      type(scene_t), intent(in) :: scene
      type(summary_t), intent(out) :: s
      integer, intent(out) :: stat
      type(job_t) :: j(1)
      character(len=16) :: tol
      write (tol, '(es10.3)') scene%tol
      j(1)%name = trim(scene%name)
      j(1)%exe = exe
      j(1)%args = [character(len=4096) :: '--overwrite', '--accuracy', adjustl(tol), deck_dir // trim(scene%name) // '.nml']
      write (output_unit, '(a)') 'accuracy_validation: ' // trim(scene%name) // ': impact --accuracy ' // trim(adjustl(tol))
      flush (output_unit)
      call run_jobs(j, stat, errmsg)
      if (stat /= 0) return
      ! exit 3: the cap reached, the errors still given
      if (j(1)%exit_code /= 0 .and. j(1)%exit_code /= 3) stat = 1
      if (stat == 0) call read_summary(out_dir // trim(scene%name) // '_summary.dat', s, stat, errmsg)
   end subroutine accuracy_run

   !> The reference runs of a scene (module header, step 2).
   subroutine plan_references(scene, s, jobs)
      type(scene_t), intent(in) :: scene
      type(summary_t), intent(in) :: s
      type(job_t), allocatable, intent(inout) :: jobs(:)
      type(deck_t) :: deck
      real(dp) :: dt, a, g0, g1, s1, gauge(2)
      integer :: nx, ny, n1x, n1y, st
      character(len=:), allocatable :: path

      path = deck_dir // trim(scene%name) // '.nml'
      call read_deck_file(path, deck, st, errmsg)
      if (st /= 0) call fail(errmsg)
      dt = summary_value(s, 'chosen_dt_us', 0.0_dp)*1.0e-6_dp
      ! the strain at the accuracy run's gauge (its ladder's: level 0's Gauss point)
      gauge = [summary_value(s, 'gauge_x_mm', 0.0_dp), summary_value(s, 'gauge_y_mm', 0.0_dp)]*1.0e-3_dp
      nx = nint(summary_value(s, 'chosen_nx', 0.0_dp))
      ny = nint(summary_value(s, 'chosen_ny', 0.0_dp))
      ! the time references on the chosen mesh, its grading included (the ladder grades its meshes)
      g0 = summary_value(s, 'chosen_grading', 1.0_dp)
      call add_impact(jobs, scene, path, 't2', dt/2.0_dp, nx, ny, g0, 2.0_dp, gauge)
      call add_impact(jobs, scene, path, 't4', dt/4.0_dp, nx, ny, g0, 4.0_dp, gauge)
      ! the contact radius at the chosen run's peak force, and the graded mesh resolving it
      a = sqrt(0.5_dp*deck%diameter*(summary_value(s, 'peak_force_N', 0.0_dp)/deck%k)**(2.0_dp/3.0_dp))
      s1 = min(first_over_radius*a, 0.25_dp*0.5_dp*deck%a/real(nx, dp))
      call graded_mesh(0.5_dp*deck%a, 0.5_dp*deck%b, s1, largest_over_side, g1, n1x, n1y)
      call add_impact(jobs, scene, path, 'm1', dt, n1x, n1y, g1, 1.0_dp, gauge)
      call add_impact(jobs, scene, path, 'm2', dt, nint(ref_factor*n1x), nint(ref_factor*n1y), &
                      g1**(1.0_dp/ref_factor), 3.0_dp, gauge)
      call add_plain(jobs, scene, path)
      if (scene%navier) then
         call add_navier(jobs, scene, path, 'n4', dt/4.0_dp, deck%t_end)
         call add_navier(jobs, scene, path, 'n8', dt/8.0_dp, deck%t_end)
      end if
   end subroutine plan_references

   !> A reference run of ./impact at dt on nx x ny graded by g.
      subroutine add_impact(jobs, scene, path, tag, dt_ref, nx_ref, ny_ref, g, weight, gauge)
         type(job_t), allocatable, intent(inout) :: jobs(:)
         type(scene_t), intent(in) :: scene
         character(len=*), intent(in) :: path, tag
         real(dp), intent(in) :: dt_ref, g, weight
         real(dp), intent(in) :: gauge(2)   !< the strain gauge (m): the accuracy run's
         integer, intent(in) :: nx_ref, ny_ref
         type(job_t) :: j
         character(len=32) :: t, gt, gx, gy
         write (t, '(es24.16)') dt_ref
         write (gx, '(es24.16)') gauge(1)
         write (gy, '(es24.16)') gauge(2)
         write (gt, '(es24.16)') g
         j%name = trim(scene%name) // '_' // tag
         j%exe = exe
         j%args = [character(len=4096) :: '--single', '--set', 'output.prefix=''' // out_dir // &
            trim(j%name) // '''', '--set', 'output.overwrite=.true.', '--set', 'analysis.dt=' // adjustl(t), &
            '--set', 'mesh.nx=' // int_str(nx_ref), '--set', 'mesh.ny=' // int_str(ny_ref), '--set', &
            'mesh.grading=' // adjustl(gt), '--set', 'output.gauge_x=' // adjustl(gx), '--set', &
            'output.gauge_y=' // adjustl(gy), path]
         j%weight = weight*real(nx_ref, dp)*real(ny_ref, dp)
         jobs = [jobs, j]
      end subroutine add_impact

   !> The plain run of the scene's deck, the unit of the ladder's price.
      subroutine add_plain(jobs, scene, path)
         type(job_t), allocatable, intent(inout) :: jobs(:)
         type(scene_t), intent(in) :: scene
         character(len=*), intent(in) :: path
         type(job_t) :: j
         j%name = trim(scene%name) // '_plain'
         j%exe = exe
         j%args = [character(len=4096) :: '--single', '--set', 'output.prefix=''' // out_dir // &
            trim(j%name) // '''', '--set', 'output.overwrite=.true.', path]
         jobs = [jobs, j]
      end subroutine add_plain

   !> A Navier reference at dt: the scene's deck with its &analysis dt
      !> replaced, written into out_dir.
      subroutine add_navier(jobs, scene, path, tag, dt_ref, t_end)
         type(job_t), allocatable, intent(inout) :: jobs(:)
         type(scene_t), intent(in) :: scene
         character(len=*), intent(in) :: path, tag
         real(dp), intent(in) :: dt_ref, t_end
         type(job_t) :: j
         j%name = trim(scene%name) // '_' // tag
         call write_navier_deck(path, out_dir // trim(j%name) // '.nml', dt_ref, t_end)
         j%exe = navier_exe
         j%args = [character(len=4096) :: out_dir // trim(j%name) // '.nml', '--out', out_dir // trim(j%name)]
         j%weight = 1.0e3_dp/(dt_ref*1.0e6_dp)
         jobs = [jobs, j]
      end subroutine add_navier

   !> The grading g and the counts of a quarter of sides lx, ly whose
   !> element at the impact point is s1 and whose largest element is
   !> `largest` times the longer side: s1 (g^n - 1)/(g - 1) = side with
   !> s1 g^(n-1) = largest, so g = (side - s1)/(side - largest).
   subroutine graded_mesh(lx, ly, s1, largest, g, nx, ny)
      real(dp), intent(in) :: lx, ly, s1, largest
      real(dp), intent(out) :: g
      integer, intent(out) :: nx, ny
      real(dp) :: big
      big = largest*max(lx, ly)
      g = max(1.0_dp, (max(lx, ly) - s1)/(max(lx, ly) - big))
      if (g <= 1.0_dp + 1.0e-9_dp) then
         g = 1.0_dp
         nx = ceiling(lx/s1);  ny = ceiling(ly/s1)
      else
         nx = ceiling(log(1.0_dp + lx*(g - 1.0_dp)/s1)/log(g))
         ny = ceiling(log(1.0_dp + ly*(g - 1.0_dp)/s1)/log(g))
      end if
   end subroutine graded_mesh

   !> The scene's deck for build/navier_impact: its lines but &analysis and
   !> &accuracy, and &analysis with the linear theory, dt and t_end.
   subroutine write_navier_deck(from, to, dt, t_end)
      character(len=*), intent(in) :: from, to
      real(dp), intent(in) :: dt, t_end
      character(len=1024) :: line
      integer :: ui, uo, ios
      open (newunit=ui, file=from, status='old', action='read')
      open (newunit=uo, file=to, status='replace', action='write')
      do
         read (ui, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (index(adjustl(line), '&analysis') == 1 .or. index(adjustl(line), '&accuracy') == 1) cycle
         write (uo, '(a)') trim(line)
      end do
      write (uo, '(a,es24.16,a,es24.16,a)') "&analysis theory = 'linear', dt = ", dt, ', t_end = ', t_end, ' /'
      close (ui)
      close (uo)
   end subroutine write_navier_deck

   !> Runs the jobs, as many at a time as the process has CPUs, the costliest
   !> first; each one's output in out_dir/<name>.log.
   subroutine run_jobs(jobs, stat, errmsg)
      type(job_t), intent(inout) :: jobs(:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer :: running, cpus, i, pid, code
      logical :: started(size(jobs))
      cpus = usable_cpus()
      running = 0
      started = .false.
      stat = 0
      do
         do while (running < cpus .and. .not. all(started))
            i = maxloc(jobs%weight, mask=.not. started, dim=1)
            started(i) = .true.
            call spawn_program(jobs(i)%exe, jobs(i)%args, out_dir // trim(jobs(i)%name) // '.log', jobs(i)%pid, &
                               stat, errmsg)
            if (stat /= 0) return
            running = running + 1
         end do
         if (running == 0) exit
         call wait_child(pid, code)
         if (pid < 0) exit
         i = findloc(jobs%pid, pid, dim=1)
         if (i == 0) cycle
         running = running - 1
         jobs(i)%exit_code = code
         jobs(i)%done = .true.
         jobs(i)%pid = -1
      end do
   end subroutine run_jobs

   !> A result of a reference run's summary (huge when absent).
   real(dp) function reference(scene, tag, iq) result(x)
      type(scene_t), intent(in) :: scene
      character(len=*), intent(in) :: tag
      integer, intent(in) :: iq
      type(summary_t) :: s
      integer :: st
      x = huge(1.0_dp)
      call read_summary(out_dir // trim(scene%name) // '_' // tag // '_summary.dat', s, st, errmsg)
      if (st == 0) x = summary_value(s, trim(keys(iq)), huge(1.0_dp))
   end function reference

   !> The cpu time of the scene's plain run (s).
   real(dp) function plain_cpu(scene) result(x)
      type(scene_t), intent(in) :: scene
      type(summary_t) :: s
      integer :: st
      call read_summary(out_dir // trim(scene%name) // '_plain_summary.dat', s, st, errmsg)
      if (st /= 0) call fail(errmsg)
      x = summary_value(s, 'cpu_s', 0.0_dp)
   end function plain_cpu

   !> The two tables (module header, step 3) and the plot's data; nfail
   !> bounds that do not hold.
   subroutine write_tables(nfail)
      integer, intent(out) :: nfail
      integer :: is, iq, ub, us, ud
      real(dp) :: q, e, e_dt, e_mesh, e_maxima, true_dt, true_mesh, truth, unc, ratio
      character(len=16) :: verdict
      character(len=:), allocatable :: parts
      real(dp), allocatable :: ratios(:)

      nfail = 0
      allocate (ratios(0))
      open (newunit=us, file=md_dir // 'accuracy_scenes.md', status='replace', action='write')
      open (newunit=ub, file=md_dir // 'accuracy_bounds.md', status='replace', action='write')
      open (newunit=ud, file=md_dir // 'accuracy_bounds.dat', status='replace', action='write')
      write (us, '(a)') '| scene | target | status | chosen dt (μs) | chosen mesh | runs | cpu (s) | ' // &
         'in plain runs | in chosen runs |'
      write (us, '(a)') '|---|---|---|---|---|---|---|---|---|'
      write (ub, '(a)') '| scene | result | value | estimated error (dt + mesh) | true error (dt + mesh) | ' // &
         'reference uncertainty | estimated / true | bound |'
      write (ub, '(a)') '|---|---|---|---|---|---|---|---|'
      write (ud, '(a)') '# scene result estimated_rel true_rel uncertainty_rel (relative errors of the results)'
      do is = 1, size(scenes)
         write (us, '(a)') '| ' // trim(scenes(is)%name) // ' | ' // real_short(scenes(is)%tol) // ' | ' // &
            text_of(acc(is), 'accuracy_status', 24) // ' | ' // real_short(summary_value(acc(is), 'chosen_dt_us', 0.0_dp)) &
            // ' | ' // int_str(nint(summary_value(acc(is), 'chosen_nx', 0.0_dp))) // ' × ' // &
            int_str(nint(summary_value(acc(is), 'chosen_ny', 0.0_dp))) // ' | ' // &
            int_str(nint(summary_value(acc(is), 'accuracy_runs', 0.0_dp))) // ' | ' // &
            real_short(summary_value(acc(is), 'accuracy_cpu_s', 0.0_dp)) // ' | ' // &
            int_str(nint(summary_value(acc(is), 'accuracy_cpu_s', 0.0_dp)/plain_cpu(scenes(is)))) // ' | ' // &
            real_short(summary_value(acc(is), 'accuracy_cpu_in_chosen_runs', 0.0_dp)) // ' |'
         do iq = 1, nq
            q = summary_value(acc(is), trim(keys(iq)), 0.0_dp)
            e = summary_value(acc(is), trim(keys(iq)) // '_error', 0.0_dp)
            e_dt = summary_value(acc(is), trim(keys(iq)) // '_error_dt', 0.0_dp)
            e_mesh = summary_value(acc(is), trim(keys(iq)) // '_error_mesh', 0.0_dp)
            e_maxima = summary_value(acc(is), trim(keys(iq)) // '_error_maxima', 0.0_dp)
            parts = real_short(e_dt) // ' + ' // real_short(e_mesh)
            if (e_maxima > 0.0_dp) parts = parts // ' + maxima ' // real_short(e_maxima)
            true_dt = q - reference(scenes(is), 't4', iq)
            true_mesh = q - reference(scenes(is), 'm2', iq)
            unc = abs(reference(scenes(is), 't2', iq) - reference(scenes(is), 't4', iq)) + &
                  abs(reference(scenes(is), 'm1', iq) - reference(scenes(is), 'm2', iq))
            truth = true_dt + true_mesh
            if (scenes(is)%navier .and. navier_has(iq)) then
               truth = q - reference(scenes(is), 'n8', iq)
               unc = abs(reference(scenes(is), 'n4', iq) - reference(scenes(is), 'n8', iq))
            end if
            verdict = 'holds'
            if (e < abs(truth) - unc) then
               verdict = '**FAILS**'
               nfail = nfail + 1
            end if
            ratio = e/max(abs(truth), unc, tiny(1.0_dp))
            ratios = [ratios, ratio]
            write (ub, '(a)') '| ' // trim(scenes(is)%name) // ' | ' // trim(keys(iq)) // ' | ' // real_short(q) // &
               ' | ' // real_short(e) // ' (' // parts // ') | ' // &
               real_short(abs(truth)) // ' (' // real_short(true_dt) // ' + ' // real_short(true_mesh) // ') | ' // &
               real_short(unc) // ' | ' // real_short(ratio) // ' | ' // trim(verdict) // ' |'
            write (ud, '(a,1x,a,3es14.5)') trim(scenes(is)%name), trim(keys(iq)), e/abs(q), abs(truth)/abs(q), &
               unc/abs(q)
         end do
      end do
      write (ub, '(a)') ''
      write (ub, '(a)') 'Bounds that hold: ' // int_str(size(ratios) - nfail) // ' of ' // int_str(size(ratios)) // &
         '; estimated / true: median ' // real_short(median(ratios)) // ', ' // int_str(count(ratios <= 10.0_dp)) // &
         ' of ' // int_str(size(ratios)) // ' within 10 times.'
      close (us)
      close (ub)
      close (ud)
   end subroutine write_tables

   !> The text of a summary's key up to its first colon (the outcome, not its reason), cut to n characters.
   function text_of(s, key, n) result(text)
      type(summary_t), intent(in) :: s
      character(len=*), intent(in) :: key
      integer, intent(in) :: n
      character(len=:), allocatable :: text
      integer :: i
      text = '-'
      i = summary_index(s, key)
      if (i == 0) return
      text = trim(s%texts(i))
      if (index(text, ':') > 1) text = text(:index(text, ':') - 1)     ! the outcome, without its reason
      text = text(:min(n, len(text)))
   end function text_of

   !> The median of x.
   real(dp) function median(x)
      real(dp), intent(in) :: x(:)
      real(dp) :: y(size(x)), t
      integer :: i, j
      y = x
      do i = 2, size(y)
         t = y(i)
         j = i - 1
         do while (j >= 1)
            if (y(j) <= t) exit
            y(j + 1) = y(j)
            j = j - 1
         end do
         y(j + 1) = t
      end do
      median = y((size(y) + 1)/2)
   end function median

   !> Stops the validation on a set-up error.
   subroutine fail(message)
      character(len=*), intent(in) :: message
      write (error_unit, '(a)') 'accuracy_validation: error: ' // trim(message)
      error stop 2
   end subroutine fail

end program accuracy_validation
