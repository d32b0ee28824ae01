!> Growing datasets of the results files over HDF5-Fortran (the rest: src/results/hdf5_io.f90, same
!> conventions): rank-1 series (a history column), rank-2 series of columns (a nodal field per
!> snapshot), grown by blocks, cut back and read whole for a restart, and virtual views of one
!> column (HDF5 1.10's VDS). Not from the paper. More: docs/OUTPUT.md.
module hdf5_series
   use, intrinsic :: iso_c_binding, only: c_ptr, c_loc
   use hdf5, only: hid_t, hsize_t, h5screate_simple_f, h5sclose_f, h5sselect_hyperslab_f, &
      h5sget_simple_extent_dims_f, H5S_UNLIMITED_F, H5S_SELECT_SET_F, H5T_NATIVE_DOUBLE, H5T_NATIVE_INTEGER, &
      h5pcreate_f, h5pset_virtual_f, h5pclose_f, H5P_DATASET_CREATE_F, h5dcreate_f, h5dopen_f, h5dclose_f, &
      h5dwrite_f, h5dread_f, h5dset_extent_f, h5dget_space_f
   use kinds, only: dp
   use hdf5_io, only: h5io_create_dataset, h5io_check, h5io_fail
   implicit none
   private
   public :: h5io_create_series, h5io_append_block, h5io_open_dataset, &
             h5io_cut_series, h5io_read_series, h5io_close_dataset, h5io_view_column, h5io_real, h5io_integer

   !> Element types of a series (h5io_create_series).
   integer, parameter :: h5io_real = 1, h5io_integer = 2

   !> Appends entries to a series at once: reals or integers (rank 1), columns x(:, k) (rank 2).
   interface h5io_append_block
      module procedure append_values, append_columns
   end interface h5io_append_block

contains

   !> Creates the empty series `name`, open as did (close with h5io_close_dataset): with nrow = 0 of
   !> rank 1, reals or integers (kind), in chunks of `chunk` entries; else reals of shape (nrow, 0)
   !> growing by columns, in chunks of `chunk` values (one column at least).
   subroutine h5io_create_series(loc, name, kind, nrow, chunk, did, stat, errmsg)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      integer, intent(in) :: kind, nrow, chunk
      integer(hid_t), intent(out) :: did
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      if (nrow == 0) then
         call h5io_create_dataset(loc, name, merge(H5T_NATIVE_INTEGER, H5T_NATIVE_DOUBLE, &
            kind == h5io_integer), [H5S_UNLIMITED_F], [int(chunk, hsize_t)], did, stat, errmsg)
      else
         call h5io_create_dataset(loc, name, H5T_NATIVE_DOUBLE, [int(nrow, hsize_t), H5S_UNLIMITED_F], &
            [int(nrow, hsize_t), int(max(1, chunk/nrow), hsize_t)], did, stat, errmsg)
      end if
   end subroutine h5io_create_series

   !> Opens the existing dataset `name` (close with h5io_close_dataset).
   subroutine h5io_open_dataset(loc, name, did, stat, errmsg)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      integer(hid_t), intent(out) :: did
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer :: err
      call h5dopen_f(loc, name, did, err)
      call h5io_check(err, 'cannot open the dataset', name, stat, errmsg)
      if (stat /= 0) did = -1
   end subroutine h5io_open_dataset

   !> The extent dims(:rank) of the series did, rank 1 or 2; rank 0 when it cannot be read.
   subroutine series_extent(did, dims, rank)
      integer(hid_t), intent(in) :: did
      integer(hsize_t), intent(out) :: dims(2)
      integer, intent(out) :: rank
      integer(hsize_t) :: maxdims(2)
      integer(hid_t) :: fspace
      integer :: err
      dims = 0;  rank = 0
      call h5dget_space_f(did, fspace, err)
      if (err == 0) call h5sget_simple_extent_dims_f(fspace, dims, maxdims, rank)
      if (err == 0) call h5sclose_f(fspace, err)
      if (err /= 0 .or. rank < 1 .or. rank > 2) rank = 0
   end subroutine series_extent

   !> Cuts the series did (n entries at least) to its first n (a restart).
   subroutine h5io_cut_series(did, n, stat, errmsg)
      integer(hid_t), intent(in) :: did
      integer, intent(in) :: n
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer(hsize_t) :: dims(2)
      integer :: err, rank
      call series_extent(did, dims, rank)
      call h5io_check(merge(0, 1, rank > 0), 'cannot read the extent of a series', '', stat, errmsg)
      if (stat /= 0) return
      if (dims(rank) < int(n, hsize_t)) then
         call h5io_fail('a series holds fewer entries than it must', '', stat, errmsg)
         return
      end if
      if (dims(rank) == int(n, hsize_t)) return
      dims(rank) = int(n, hsize_t)
      call h5dset_extent_f(did, dims(:rank), err)
      call h5io_check(err, 'cannot cut a series', '', stat, errmsg)
   end subroutine h5io_cut_series

   !> The values of the rank-1 series `name` as reals (a restart; HDF5
   !> converts integers, exactly below 2**53).
   subroutine h5io_read_series(loc, name, x, stat, errmsg)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      real(dp), allocatable, target, intent(out) :: x(:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer(hid_t) :: did
      integer(hsize_t) :: dims(2)
      type(c_ptr) :: at
      integer :: err, rank
      call h5io_open_dataset(loc, name, did, stat, errmsg)
      if (stat /= 0) return
      call series_extent(did, dims, rank)
      allocate (x(dims(max(rank, 1))))
      err = 0
      at = c_loc(x)                          ! (h5dread_f's buffer is intent(inout))
      if (size(x) > 0) call h5dread_f(did, H5T_NATIVE_DOUBLE, at, err)
      call h5io_check(err, 'cannot read the dataset', name, stat, errmsg)
      call h5dclose_f(did, err)
   end subroutine h5io_read_series

   !> Appends the reals or integers x(:) to the rank-1 series did.
   subroutine append_values(did, x, stat, errmsg)
      integer(hid_t), intent(in) :: did
      class(*), intent(in) :: x(:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      real(dp), allocatable, target :: r(:)
      integer, allocatable, target :: i(:)
      stat = 0
      if (size(x) == 0) return
      select type (x)
      type is (real(dp))
         r = x
         call grow_and_write(did, H5T_NATIVE_DOUBLE, 1, size(x), c_loc(r), stat, errmsg)
      type is (integer)
         i = x
         call grow_and_write(did, H5T_NATIVE_INTEGER, 1, size(x), c_loc(i), stat, errmsg)
      end select
   end subroutine append_values

   !> Appends the columns x(:, k) (nrow values each) to the rank-2 series did.
   subroutine append_columns(did, x, stat, errmsg)
      integer(hid_t), intent(in) :: did
      real(dp), intent(in), target, contiguous :: x(:,:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      stat = 0
      if (size(x, 2) == 0) return
      call grow_and_write(did, H5T_NATIVE_DOUBLE, 2, size(x, 2), c_loc(x), stat, errmsg)
   end subroutine append_columns

   !> Extends did's last dimension by n and writes the values at buf (type tid) there.
   subroutine grow_and_write(did, tid, rank, n, buf, stat, errmsg)
      integer(hid_t), intent(in) :: did, tid
      integer, intent(in) :: rank, n
      type(c_ptr), intent(in) :: buf
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer(hsize_t) :: dims(2), start(rank), count(rank)
      integer(hid_t) :: fspace, mspace
      integer :: err, found
      call series_extent(did, dims, found)
      call h5io_check(merge(0, 1, found == rank), 'cannot read the extent of a series', '', stat, errmsg)
      if (stat /= 0) return
      start = 0
      start(rank) = dims(rank)
      count = dims(:rank)
      count(rank) = int(n, hsize_t)
      dims(rank) = dims(rank) + int(n, hsize_t)
      call h5dset_extent_f(did, dims(:rank), err)
      call h5io_check(err, 'cannot extend a series', '', stat, errmsg)
      if (stat /= 0) return
      call h5dget_space_f(did, fspace, err)
      if (err == 0) call h5sselect_hyperslab_f(fspace, H5S_SELECT_SET_F, start, count, err)
      if (err == 0) call h5screate_simple_f(rank, count, mspace, err)
      call h5io_check(err, 'cannot select the new entry of a series', '', stat, errmsg)
      if (stat /= 0) return
      call h5dwrite_f(did, tid, buf, err, mem_space_id=mspace, file_space_id=fspace)
      call h5io_check(err, 'cannot write the new entry of a series', '', stat, errmsg)
      call h5sclose_f(mspace, err)
      call h5sclose_f(fspace, err)
   end subroutine grow_and_write

   !> Creates `name`, a virtual dataset (VDS) of nrow reals showing column `column`
   !> of the rank-2 series `source` of `source_file` ('.': the same): a view, no copy.
   subroutine h5io_view_column(loc, name, source_file, source, nrow, column, stat, errmsg)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name, source_file, source
      integer, intent(in) :: nrow, column
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer(hid_t) :: vspace, sspace, plist, did
      integer :: err
      call h5screate_simple_f(1, [int(nrow, hsize_t)], vspace, err)
      call h5io_check(err, 'cannot make the dataspace of the view', name, stat, errmsg)
      if (stat /= 0) return
      call h5screate_simple_f(2, [int(nrow, hsize_t), int(column, hsize_t)], sspace, err, &
         [int(nrow, hsize_t), H5S_UNLIMITED_F])
      if (err == 0) call h5sselect_hyperslab_f(sspace, H5S_SELECT_SET_F, [0_hsize_t, int(column - 1, hsize_t)], &
         [int(nrow, hsize_t), 1_hsize_t], err)
      if (err == 0) call h5pcreate_f(H5P_DATASET_CREATE_F, plist, err)
      if (err == 0) call h5pset_virtual_f(plist, vspace, source_file, source, sspace, err)
      call h5io_check(err, 'cannot map the view onto '//source, name, stat, errmsg)
      if (stat == 0) then
         call h5dcreate_f(loc, name, H5T_NATIVE_DOUBLE, vspace, did, err, dcpl_id=plist)
         call h5io_check(err, 'cannot create the view', name, stat, errmsg)
         if (stat == 0) call h5dclose_f(did, err)
         call h5pclose_f(plist, err)
      end if
      call h5sclose_f(sspace, err)
      call h5sclose_f(vspace, err)
   end subroutine h5io_view_column

   !> Closes a dataset opened by h5io_create_series or h5io_open_dataset.
   subroutine h5io_close_dataset(did, stat, errmsg)
      integer(hid_t), intent(in) :: did
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer :: err
      call h5dclose_f(did, err)
      call h5io_check(err, 'cannot close a dataset', '', stat, errmsg)
   end subroutine h5io_close_dataset

end module hdf5_series
