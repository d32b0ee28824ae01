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
!>    --version      the version of the impact it was built with, and the licence
!>
!> Installed (make install) as impact-h5export, out of HDF5's own h5*
!> names; bin/h5export is a link to it for one release.
!>
!> Output: '#' lines naming the file, the snapshot (step, time, force) and
!> the columns with their units, then x_mm y_mm <field>_mm (or _rad for the
!> rotations), one grid line of constant x per block, blocks separated by a
!> blank line: gnuplot's grid format for `splot ... with pm3d`.
!> Build: make h5export (mk/hdf5.mk). Exit status 1 with a message on
!> error: every read is checked (a dataset whose checksum, HDF5's
!> Fletcher32 filter, does not match its data is a read error; so is
!> anything else HDF5 reports, tools/hdf5_read.f90), and every write of
!> the table, its flush and its close (a full disk), so that a damaged
!> file or a table cut short never passes for an export.
program h5export
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit, int64
   use hdf5, only: hid_t
   use kinds, only: dp, msg_len
   use hdf5_io, only: h5io_start, h5io_close
   use hdf5_read, only: h5io_open_read, h5io_get_attr, h5io_read
   use process_stop, only: exit_program, keep_file_size_errors
   use file_system, only: path_kind, path_regular, file_size
   use build_info, only: code_version
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
   integer(int64) :: bytes

   call keep_file_size_errors()       ! past ulimit -f a write fails and is reported
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
            '[--snapshot peak|last|K] [--quarter] [--version]'
         stop
      case ('--version')
         write (output_unit, '(a/a)') 'impact-h5export (' // code_version // ')', &
            'License MIT: <https://opensource.org/licenses/MIT>.'
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
   if (stat /= 0) call fail(trim(path)//': '//errmsg)
   if (size(values) /= size(xy, 2)) call fail(trim(path)//': the field and /mesh/coordinates differ in size')
   if (any(grid < 1 .or. grid > size(xy, 2))) &
      call fail(trim(path)//': /mesh/grid names nodes that /mesh/coordinates does not hold (a damaged file)')

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
   bytes = 0
   call write_table(ios, errmsg)
   if (ios == 0) flush (out, iostat=ios, iomsg=errmsg)
   if (ios == 0 .and. out /= output_unit) close (out, iostat=ios, iomsg=errmsg)
   if (ios /= 0) then
      if (len_trim(out_path) == 0) out_path = '(standard output)'
      call fail('cannot write '//trim(out_path)//': '//errmsg)
   end if
   ! gfortran 12 reports no failed write(2) (a full disk, ulimit -f): the length on disk does
   if (len_trim(out_path) > 0) then
      if (path_kind(trim(out_path)) == path_regular) then
         if (file_size(trim(out_path)) /= bytes) call fail('cannot write '//trim(out_path)// &
            ': the table did not reach the disk whole (a full disk, or the file-size limit)')
      end if
   end if

contains

   !> The table on unit `out`: the '#' header, then one grid line of
   !> constant x per block; ios /= 0 and iomsg at the first write that
   !> fails. bytes counts what was written (put).
   subroutine write_table(ios, iomsg)
      integer, intent(out) :: ios
      character(len=*), intent(inout) :: iomsg
      character(len=256) :: line
      call put('# h5export: '//trim(field)//' from '//trim(path), ios, iomsg)
      if (snapshot == 'peak') then
         write (line, '(a,i0,a,es14.6,a,es14.6,a)') '# snapshot: peak force, step ', step, ', time ', time*us_per_s, &
            ' us, force ', force, ' N'
      else
         write (line, '(a,i0,a,i0,a,es14.6,a,es14.6,a)') '# snapshot ', k, ': step ', step, ', time ', &
            time*us_per_s, ' us, force ', force, ' N'
      end if
      if (ios == 0) call put(trim(line), ios, iomsg)
      if (mirror) then
         line = '# the quarter model mirrored about x = 0 and y = 0 into the whole plate'
      else
         line = "# the modelled domain ('"//domain//"')"
      end if
      if (ios == 0) call put(trim(line), ios, iomsg)
      if (ios == 0) call put('# columns: x_mm (mm), y_mm (mm), '//trim(field)//'_'//unit_name//' ('//unit_name//')', &
         ios, iomsg)
      if (ios == 0) call put('# x_mm y_mm '//trim(field)//'_'//unit_name, ios, iomsg)
      scan_lines: do i = istart, nxg
         do j = jstart, nyg
            ii = abs(i);  jj = abs(j)
            sx = 1.0_dp;  sy = 1.0_dp
            if (i < 0) sx = -1.0_dp
            if (j < 0) sy = -1.0_dp
            associate (n => grid(ii + 1, jj + 1))
               write (line(:48), '(3es16.7e3)') sx*xy(1, n)*mm_per_m, sy*xy(2, n)*mm_per_m, &
                  merge(parity_x(ifield), 1.0_dp, i < 0)*merge(parity_y(ifield), 1.0_dp, j < 0)*values(n)*scale
            end associate
            if (ios == 0) call put(line(:48), ios, iomsg)
         end do
         if (ios == 0) call put('', ios, iomsg)
         if (ios /= 0) exit scan_lines
      end do scan_lines
   end subroutine write_table

   !> One line of the table, its length and end of line added to bytes.
   subroutine put(text, ios, iomsg)
      character(len=*), intent(in) :: text
      integer, intent(out) :: ios
      character(len=*), intent(inout) :: iomsg
      write (out, '(a)', iostat=ios, iomsg=iomsg) text
      bytes = bytes + len(text) + 1
   end subroutine put

   subroutine fail(message)
      character(len=*), intent(in) :: message
      write (error_unit, '(a)') 'h5export: error: '//trim(message)
      call exit_program(1)
   end subroutine fail

end program h5export
