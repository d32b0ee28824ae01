!> h5export: one nodal field of a results file <prefix>.h5 as gnuplot grid
!> data, for a picture of the deflected plate (postproc/shape.gp).
!>
!> Usage:
!>    build/h5export FILE.h5 [-o OUT] [--field w|u|v|psi_x|psi_y]
!>                           [--snapshot peak|last|K] [--quarter]
!>
!>    -o OUT         write to OUT (default: standard output)
!>    --field        the field (default w, the deflection)
!>    --snapshot     'peak' (default): the step of the largest contact force,
!>                   /peak; 'last': the last snapshot of /fields; K: the K-th
!>                   snapshot of /fields, from 1
!>    --quarter      keep the modelled quarter as it is; by default a quarter
!>                   model is mirrored about x = 0 and y = 0 into the whole
!>                   plate (w, v, psi_y are even in x; u, psi_x odd; w, u,
!>                   psi_x even in y; v, psi_y odd: the quarter model's
!>                   symmetry, src/model/mesh.f90)
!>
!> Output: '#' lines naming the file, the snapshot (step, time, force) and
!> the columns with their units, then x_mm y_mm <field>_mm (or _rad for the
!> rotations), one grid line of constant x per block, blocks separated by a
!> blank line: gnuplot's grid format for `splot ... with pm3d`.
!> Build: make h5export (mk/hdf5.mk). Exit status 1 with a message on error.
program h5export
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use hdf5, only: hid_t
   use kinds, only: dp, msg_len
   use hdf5_io, only: h5io_start, h5io_close
   use hdf5_read, only: h5io_open_read, h5io_get_attr, h5io_read
   use process_stop, only: exit_program
   implicit none

   !> Metres to millimetres.
   real(dp), parameter :: mm_per_m = 1.0e3_dp
   !> Seconds to microseconds.
   real(dp), parameter :: us_per_s = 1.0e6_dp
   character(len=*), parameter :: fields(5) = ['w    ', 'u    ', 'v    ', 'psi_x', 'psi_y']
   !> Parity of each field under x -> -x and y -> -y in the quarter model.
   real(dp), parameter :: parity_x(5) = [1.0_dp, -1.0_dp, 1.0_dp, -1.0_dp, 1.0_dp]
   real(dp), parameter :: parity_y(5) = [1.0_dp, 1.0_dp, -1.0_dp, 1.0_dp, -1.0_dp]

   character(len=msg_len) :: path, out_path, field, snapshot, arg, errmsg
   character(len=:), allocatable :: domain, unit_name
   logical :: mirror
   integer(hid_t) :: fid
   integer :: stat, iarg, nsnap, k, ifield, out, ios, nxg, nyg, i, j, ii, jj, step, istart, jstart
   integer, allocatable :: grid(:,:), steps(:)
   real(dp), allocatable :: xy(:,:), values(:), all_values(:,:), times(:), forces(:)
   real(dp) :: time, force, scale, sx, sy

   ! -- arguments
   path = '';  out_path = '';  field = 'w';  snapshot = 'peak';  mirror = .true.
   iarg = 1
   arguments: do while (iarg <= command_argument_count())
      call get_command_argument(iarg, arg)
      select case (arg)
      case ('-o', '--field', '--snapshot')
         if (iarg == command_argument_count()) call fail(trim(arg)//' needs a value')
         iarg = iarg + 1
         if (arg == '-o') call get_command_argument(iarg, out_path)
         if (arg == '--field') call get_command_argument(iarg, field)
         if (arg == '--snapshot') call get_command_argument(iarg, snapshot)
      case ('--quarter')
         mirror = .false.
      case ('-h', '--help')
         write (output_unit, '(a)') 'usage: h5export FILE.h5 [-o OUT] [--field w|u|v|psi_x|psi_y] '// &
            '[--snapshot peak|last|K] [--quarter]'
         stop
      case default
         if (arg(1:1) == '-') call fail('unknown option '//trim(arg))
         if (len_trim(path) > 0) call fail('give one file: '//trim(path)//' and '//trim(arg))
         path = arg
      end select
      iarg = iarg + 1
   end do arguments
   if (len_trim(path) == 0) call fail('usage: h5export FILE.h5 [-o OUT] [--field F] [--snapshot peak|last|K] [--quarter]')
   ifield = findloc(fields, trim(field), dim=1)
   if (ifield == 0) call fail("--field "//trim(field)//": must be one of w, u, v, psi_x, psi_y")

   ! -- the mesh and the field
   errmsg = ''
   call h5io_start(stat, errmsg)
   if (stat == 0) call h5io_open_read(trim(path), fid, stat, errmsg)
   if (stat /= 0) call fail(errmsg)
   call h5io_get_attr(fid, 'mesh', 'domain', domain, stat, errmsg)
   if (stat == 0) call h5io_read(fid, 'mesh/grid', grid, stat, errmsg)
   if (stat == 0) call h5io_read(fid, 'mesh/coordinates', xy, stat, errmsg)
   if (stat /= 0) call fail(trim(path)//': '//errmsg)
   if (snapshot == 'peak') then
      call h5io_read(fid, 'peak/'//trim(field), values, stat, errmsg)
      if (stat == 0) call h5io_get_attr(fid, 'peak', 'step', step, stat, errmsg)
      if (stat == 0) call h5io_get_attr(fid, 'peak', 'time', time, stat, errmsg)
      if (stat == 0) call h5io_get_attr(fid, 'peak', 'force', force, stat, errmsg)
      if (stat /= 0) call fail(trim(path)//': '//errmsg)
   else
      call h5io_read(fid, 'fields/'//trim(field), all_values, stat, errmsg)
      if (stat == 0) call h5io_read(fid, 'fields/step', steps, stat, errmsg)
      if (stat == 0) call h5io_read(fid, 'fields/time', times, stat, errmsg)
      if (stat == 0) call h5io_read(fid, 'fields/force', forces, stat, errmsg)
      if (stat /= 0) call fail(trim(path)//': '//errmsg)
      nsnap = min(size(all_values, 2), size(steps), size(times), size(forces))
      if (nsnap == 0) call fail(trim(path)//': /fields holds no snapshot yet')
      if (snapshot == 'last') then
         k = nsnap
      else
         read (snapshot, *, iostat=ios) k
         if (ios /= 0) call fail('--snapshot '//trim(snapshot)//': peak, last or a snapshot number')
         if (k < 1 .or. k > nsnap) then
            write (errmsg, '(a,i0,a)') '--snapshot '//trim(snapshot)//': the file has snapshots 1 to ', nsnap, &
               ' (/fields/step)'
            call fail(errmsg)
         end if
      end if
      values = all_values(:, k)
      step = steps(k);  time = times(k);  force = forces(k)
   end if
   call h5io_close(fid, stat, errmsg)
   if (size(values) /= size(xy, 2)) call fail(trim(path)//': the field and /mesh/coordinates differ in size')

   ! -- the table, scan line by scan line (constant x)
   if (ifield >= 4) then
      scale = 1.0_dp;  unit_name = 'rad'
   else
      scale = mm_per_m;  unit_name = 'mm'
   end if
   mirror = mirror .and. domain == 'quarter'
   nxg = size(grid, 1) - 1
   nyg = size(grid, 2) - 1
   istart = 0;  jstart = 0
   if (mirror) then
      istart = -nxg;  jstart = -nyg
   end if
   if (len_trim(out_path) > 0) then
      open (newunit=out, file=trim(out_path), status='replace', action='write', iostat=ios, iomsg=errmsg)
      if (ios /= 0) call fail('cannot write '//trim(out_path)//': '//errmsg)
   else
      out = output_unit
   end if
   write (out, '(a)') '# h5export: '//trim(field)//' from '//trim(path)
   if (snapshot == 'peak') then
      write (out, '(a,i0,a,es14.6,a,es14.6,a)') '# snapshot: peak force, step ', step, ', time ', time*us_per_s, &
         ' us, force ', force, ' N'
   else
      write (out, '(a,i0,a,i0,a,es14.6,a,es14.6,a)') '# snapshot ', k, ': step ', step, ', time ', &
         time*us_per_s, ' us, force ', force, ' N'
   end if
   if (mirror) then
      write (out, '(a)') '# the quarter model mirrored about x = 0 and y = 0 into the whole plate'
   else
      write (out, '(a)') "# the modelled domain ('"//domain//"')"
   end if
   write (out, '(a)') '# columns: x_mm (mm), y_mm (mm), '//trim(field)//'_'//unit_name//' ('//unit_name//')'
   write (out, '(a)') '# x_mm y_mm '//trim(field)//'_'//unit_name
   scan_lines: do i = istart, nxg
      do j = jstart, nyg
         ii = abs(i);  jj = abs(j)
         sx = 1.0_dp;  sy = 1.0_dp
         if (i < 0) sx = -1.0_dp
         if (j < 0) sy = -1.0_dp
         associate (n => grid(ii + 1, jj + 1))
            write (out, '(3es16.7e3)') sx*xy(1, n)*mm_per_m, sy*xy(2, n)*mm_per_m, &
               merge(parity_x(ifield), 1.0_dp, i < 0)*merge(parity_y(ifield), 1.0_dp, j < 0)*values(n)*scale
         end associate
      end do
      write (out, '(a)') ''
   end do scan_lines
   if (out /= output_unit) close (out)

contains

   subroutine fail(message)
      character(len=*), intent(in) :: message
      write (error_unit, '(a)') 'h5export: error: '//trim(message)
      call exit_program(1)
   end subroutine fail

end program h5export
