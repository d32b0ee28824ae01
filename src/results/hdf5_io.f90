!> Thin checked wrappers over HDF5-Fortran for the results file
!> (src/results/results_hdf5.f90) and the tools that read it (tools/h5export.f90).
!>
!> Every routine returns `stat` (0 on success) and, on failure, `errmsg`, a
!> message naming the operation and the object; the library's own error
!> printing is switched off by h5io_start, so a failure reads as one line of
!> the caller's. The arguments recur: `loc` is the file or group a path
!> starts from, `name` a path relative to it (`obj` and `name` an object's
!> path and its attribute's name), `did` an open dataset.
!>
!> What is written, and how a reader sees it:
!>  - attributes are scalars (dataspace SCALAR: h5py gives a number or a
!>    str, not a one-element array), or 1-D arrays (h5io_set_attr with an
!>    array); strings are variable-length UTF-8 (h5py gives str);
!>  - fixed datasets are written whole with the high-level H5LT calls;
!>  - series are extendible chunked datasets that grow by a block of
!>    entries per h5io_append_block: rank 1
!>    (n) for a history column, rank 2 (nrow, n) in
!>    Fortran order, i.e. (n, nrow) in C order, h5py and h5dump, for a field
!>    of nrow nodes per snapshot.
!> Arrays keep Fortran order on disk: a Fortran x(m, n) reads as x[n, m] in
!> h5py and h5dump (C order).
!>
!> Nothing is cached here: the caller holds the file and dataset ids. This
!> is the write half, what the program needs; the tools that read a results
!> file (tools/h5export.f90, the tests) have the read half,
!> tools/hdf5_read.f90, over the same messages (h5io_check, h5io_fail).
module hdf5_io
   use, intrinsic :: iso_c_binding, only: c_ptr, c_loc, c_char, c_null_char, c_bool, c_int, c_int64_t
   use hdf5, only: hid_t, hsize_t, size_t, h5open_f, h5eset_auto_f, h5fcreate_f, h5fclose_f, &
      h5fflush_f, H5F_ACC_TRUNC_F, H5F_SCOPE_GLOBAL_F, h5gcreate_f, h5gclose_f, &
      h5screate_f, h5screate_simple_f, h5sclose_f, h5sselect_hyperslab_f, h5sget_simple_extent_dims_f, &
      H5S_SCALAR_F, H5S_UNLIMITED_F, H5S_SELECT_SET_F, &
      h5acreate_by_name_f, h5awrite_f, h5aclose_f, h5aexists_by_name_f, h5adelete_by_name_f, &
      h5tcopy_f, h5tset_size_f, h5tset_cset_f, h5tclose_f, &
      H5T_NATIVE_DOUBLE, H5T_NATIVE_INTEGER, H5T_FORTRAN_S1, H5T_CSET_UTF8_F, h5tset_strpad_f, &
      H5T_STR_NULLTERM_F, &
      h5pcreate_f, h5pset_chunk_f, h5pset_virtual_f, h5pclose_f, H5P_DATASET_CREATE_F, &
      H5P_FILE_ACCESS_F, &
      h5dcreate_f, h5dopen_f, h5dclose_f, h5dwrite_f, h5dset_extent_f, h5dget_space_f
   use h5lt, only: h5ltmake_dataset_double_f, h5ltmake_dataset_int_f
   use kinds, only: dp
   implicit none
   private
   public :: h5io_start, h5io_create, h5io_close, h5io_flush, h5io_group
   public :: h5io_set_attr, h5io_write, h5io_rewrite
   public :: h5io_check, h5io_fail, h5io_attr_path, h5io_vlen_string_type
   public :: h5io_create_series, h5io_create_columns, h5io_append_block, h5io_close_dataset
   public :: h5io_view_column
   public :: h5io_real, h5io_integer

   !> Element types of a series (h5io_create_series).
   integer, parameter :: h5io_real = 1, h5io_integer = 2
   !> Status returned on any failure.
   integer, parameter :: failed = 1
   !> The size of a variable-length string type: HDF5's H5T_VARIABLE,
   !> (size_t)(-1) in C, which the HDF5 1.10 Fortran module does not define.
   integer(size_t), parameter :: variable_length = -1_size_t

   !> Writes an attribute: a real(dp), integer or string scalar, or a real(dp)
   !> or integer 1-D array.
   interface h5io_set_attr
      module procedure set_attr_scalar, set_attr_array
   end interface h5io_set_attr

   !> Writes a whole dataset (H5LT): real(dp) or integer, rank 1 or 2.
   interface h5io_write
      module procedure write_1d, write_2d
   end interface h5io_write

   !> Appends several entries to a series at once: reals or integers to a
   !> rank-1 series, the columns x(:, k) to a rank-2 series (one extension
   !> and one write for all of them).
   interface h5io_append_block
      module procedure append_reals, append_integers, append_columns
   end interface h5io_append_block

contains

   ! ------------------------------------------------------------ files, groups

   !> Opens the HDF5 library (its predefined types) and switches off its own
   !> error printing. Safe to call more than once.
   subroutine h5io_start(stat, errmsg)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer :: err
      call h5open_f(err)
      if (err == 0) call h5eset_auto_f(0, err)
      call h5io_check(err, 'cannot initialise the HDF5 library', '', stat, errmsg)
   end subroutine h5io_start

   !> Creates (or truncates) the file `path` for writing; fid is its id.
   !> The file evicts an object's metadata from HDF5's cache when the object
   !> is closed (H5Pset_evict_on_close, HDF5 >= 1.10.1; no Fortran wrapper
   !> in 1.10, so through its C interface): the views of src/results/results_xdmf.f90,
   !> made and closed by the thousand, would otherwise fill the cache, which
   !> every flush walks.
   subroutine h5io_create(path, fid, stat, errmsg)
      character(len=*), intent(in) :: path
      integer(hid_t), intent(out) :: fid
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer :: err
      integer(hid_t) :: fapl
      interface
         !> herr_t H5Pset_evict_on_close(hid_t fapl_id, hbool_t evict_on_close); hbool_t is C's bool
         function c_h5pset_evict_on_close(fapl_id, evict) bind(c, name='H5Pset_evict_on_close') result(r)
            import :: c_int64_t, c_bool, c_int
            integer(c_int64_t), value :: fapl_id     ! hid_t: int64_t since HDF5 1.10
            logical(c_bool), value :: evict
            integer(c_int) :: r
         end function c_h5pset_evict_on_close
      end interface
      call h5pcreate_f(H5P_FILE_ACCESS_F, fapl, err)
      if (err == 0) err = int(c_h5pset_evict_on_close(int(fapl, c_int64_t), .true._c_bool))
      call h5io_check(err, 'cannot set evict-on-close for the HDF5 file', path, stat, errmsg)
      if (stat /= 0) return
      call h5fcreate_f(path, H5F_ACC_TRUNC_F, fid, err, access_prp=fapl)
      call h5io_check(err, 'cannot create the HDF5 file', path, stat, errmsg)
      call h5pclose_f(fapl, err)
   end subroutine h5io_create

   !> Closes the file fid.
   subroutine h5io_close(fid, stat, errmsg)
      integer(hid_t), intent(in) :: fid
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer :: err
      call h5fclose_f(fid, err)
      call h5io_check(err, 'cannot close the HDF5 file', '', stat, errmsg)
   end subroutine h5io_close

   !> Writes everything buffered to the file fid (H5Fflush), so that a run
   !> killed later leaves a file that opens with all it had written so far.
   subroutine h5io_flush(fid, stat, errmsg)
      integer(hid_t), intent(in) :: fid
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer :: err
      call h5fflush_f(fid, H5F_SCOPE_GLOBAL_F, err)
      call h5io_check(err, 'cannot flush the HDF5 file', '', stat, errmsg)
   end subroutine h5io_flush

   !> Creates the group `name` (its parent must exist).
   subroutine h5io_group(loc, name, stat, errmsg)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer(hid_t) :: gid
      integer :: err
      call h5gcreate_f(loc, name, gid, err)
      call h5io_check(err, 'cannot create the group', name, stat, errmsg)
      if (stat /= 0) return
      call h5gclose_f(gid, err)
      call h5io_check(err, 'cannot close the group', name, stat, errmsg)
   end subroutine h5io_group

   ! ------------------------------------------------------------ attributes

   !> Scalar attribute `name` of object `obj`: real(dp), integer or a string
   !> (variable-length UTF-8, trailing blanks removed).
   subroutine set_attr_scalar(loc, obj, name, x, stat, errmsg)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: obj, name
      class(*), intent(in), target :: x
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      character(kind=c_char), allocatable, target :: chars(:)
      type(c_ptr), target :: ptr(1)
      integer(hid_t) :: tid
      integer :: err, k
      select type (x)
      type is (real(dp))
         call put_attr(loc, obj, name, H5T_NATIVE_DOUBLE, c_loc(x), 0, stat, errmsg)
      type is (integer)
         call put_attr(loc, obj, name, H5T_NATIVE_INTEGER, c_loc(x), 0, stat, errmsg)
      type is (character(len=*))
         chars = [(x(k:k), k = 1, len_trim(x)), c_null_char]
         ptr(1) = c_loc(chars)
         call h5io_vlen_string_type(tid, err)
         call h5io_check(err, 'cannot make a string type for the attribute', name, stat, errmsg)
         if (stat /= 0) return
         call put_attr(loc, obj, name, tid, c_loc(ptr), 0, stat, errmsg)
         call h5tclose_f(tid, err)
      class default
         call h5io_fail('an attribute is a real(dp), an integer or a string', h5io_attr_path(obj, name), &
            stat, errmsg)
      end select
   end subroutine set_attr_scalar

   !> 1-D array attribute `name` of object `obj` (at least one value):
   !> real(dp) or integer.
   subroutine set_attr_array(loc, obj, name, x, stat, errmsg)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: obj, name
      class(*), intent(in) :: x(:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      real(dp), allocatable, target :: r(:)
      integer, allocatable, target :: i(:)
      select type (x)
      type is (real(dp))
         r = x
         call put_attr(loc, obj, name, H5T_NATIVE_DOUBLE, c_loc(r), size(r), stat, errmsg)
      type is (integer)
         i = x
         call put_attr(loc, obj, name, H5T_NATIVE_INTEGER, c_loc(i), size(i), stat, errmsg)
      class default
         call h5io_fail('an array attribute is real(dp) or integer', h5io_attr_path(obj, name), stat, errmsg)
      end select
   end subroutine set_attr_array

   !> Creates (replacing one of the same name) and writes an attribute of
   !> type tid from the address buf: a scalar when n = 0, else n values.
   subroutine put_attr(loc, obj, name, tid, buf, n, stat, errmsg)
      integer(hid_t), intent(in) :: loc, tid
      character(len=*), intent(in) :: obj, name
      type(c_ptr), intent(in) :: buf
      integer, intent(in) :: n
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer(hid_t) :: sid, aid
      integer :: err
      logical :: there

      call h5aexists_by_name_f(loc, obj, name, there, err)
      call h5io_check(err, 'cannot look for the attribute', h5io_attr_path(obj, name), stat, errmsg)
      if (stat /= 0) return
      if (there) then
         call h5adelete_by_name_f(loc, obj, name, err)
         call h5io_check(err, 'cannot replace the attribute', h5io_attr_path(obj, name), stat, errmsg)
         if (stat /= 0) return
      end if
      if (n == 0) then
         call h5screate_f(H5S_SCALAR_F, sid, err)
      else
         call h5screate_simple_f(1, [int(n, hsize_t)], sid, err)
      end if
      call h5io_check(err, 'cannot make the dataspace of the attribute', h5io_attr_path(obj, name), stat, errmsg)
      if (stat /= 0) return
      call h5acreate_by_name_f(loc, obj, name, tid, sid, aid, err)
      call h5io_check(err, 'cannot create the attribute', h5io_attr_path(obj, name), stat, errmsg)
      if (stat == 0) then
         call h5awrite_f(aid, tid, buf, err)
         call h5io_check(err, 'cannot write the attribute', h5io_attr_path(obj, name), stat, errmsg)
         call h5aclose_f(aid, err)
      end if
      call h5sclose_f(sid, err)
   end subroutine put_attr

   !> A variable-length, null-terminated UTF-8 string type (the caller closes
   !> it), made from the one-character type H5T_FORTRAN_S1: the module's
   !> H5T_STRING is already variable-length in HDF5 1.10 and cannot be resized.
   subroutine h5io_vlen_string_type(tid, err)
      integer(hid_t), intent(out) :: tid  !< the new type
      integer, intent(out) :: err         !< HDF5's error code (0 on success)
      call h5tcopy_f(H5T_FORTRAN_S1, tid, err)
      if (err == 0) call h5tset_size_f(tid, variable_length, err)
      if (err == 0) call h5tset_strpad_f(tid, H5T_STR_NULLTERM_F, err)
      if (err == 0) call h5tset_cset_f(tid, H5T_CSET_UTF8_F, err)
   end subroutine h5io_vlen_string_type

   ! ------------------------------------------------------------ whole datasets

   !> Writes the dataset `name` of the 1-D array x: real(dp) or integer.
   subroutine write_1d(loc, name, x, stat, errmsg)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      class(*), intent(in) :: x(:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      call make_dataset(loc, name, shape(x, kind=hsize_t), x, stat, errmsg)
   end subroutine write_1d

   !> Writes the dataset `name` of the 2-D array x, real(dp) or integer
   !> (x(m, n) reads as x[n, m] in C order).
   subroutine write_2d(loc, name, x, stat, errmsg)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      class(*), intent(in) :: x(:,:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      stat = 1
      select type (x)
      type is (real(dp))
         call make_dataset(loc, name, shape(x, kind=hsize_t), reshape(x, [size(x)]), stat, errmsg)
      type is (integer)
         call make_dataset(loc, name, shape(x, kind=hsize_t), reshape(x, [size(x)]), stat, errmsg)
      end select
   end subroutine write_2d

   !> Writes the dataset `name` of shape dims (Fortran order) from the
   !> values x, in array element order: real(dp) or integer.
   subroutine make_dataset(loc, name, dims, x, stat, errmsg)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      integer(hsize_t), intent(in) :: dims(:)
      class(*), intent(in) :: x(:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer :: err
      err = -1
      select type (x)
      type is (real(dp))
         call h5ltmake_dataset_double_f(loc, name, size(dims), dims, x, err)
      type is (integer)
         call h5ltmake_dataset_int_f(loc, name, size(dims), dims, x, err)
      end select
      call h5io_check(err, 'cannot write the dataset', name, stat, errmsg)
   end subroutine make_dataset

   !> Overwrites the whole existing real dataset `name` with x(:), which must
   !> have its size.
   subroutine h5io_rewrite(loc, name, x, stat, errmsg)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: x(:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer(hid_t) :: did
      integer :: err
      call h5dopen_f(loc, name, did, err)
      call h5io_check(err, 'cannot open the dataset', name, stat, errmsg)
      if (stat /= 0) return
      call h5dwrite_f(did, H5T_NATIVE_DOUBLE, x, shape(x, kind=hsize_t), err)
      call h5io_check(err, 'cannot write the dataset', name, stat, errmsg)
      call h5dclose_f(did, err)
   end subroutine h5io_rewrite

   ! ------------------------------------------------------------ series

   !> Creates the empty extendible rank-1 dataset `name` of reals or integers
   !> (kind = h5io_real or h5io_integer), stored in chunks of `chunk` entries,
   !> and returns it open as did (close with h5io_close_dataset).
   subroutine h5io_create_series(loc, name, kind, chunk, did, stat, errmsg)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      integer, intent(in) :: kind, chunk
      integer(hid_t), intent(out) :: did
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer(hid_t) :: tid
      tid = merge(H5T_NATIVE_INTEGER, H5T_NATIVE_DOUBLE, kind == h5io_integer)
      call create_extendible(loc, name, tid, [0_hsize_t], [int(chunk, hsize_t)], did, stat, errmsg)
   end subroutine h5io_create_series

   !> Creates the empty extendible real dataset `name` of shape (nrow, 0),
   !> growing by whole columns of nrow values (one chunk each), and returns
   !> it open as did.
   subroutine h5io_create_columns(loc, name, nrow, did, stat, errmsg)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      integer, intent(in) :: nrow
      integer(hid_t), intent(out) :: did
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      call create_extendible(loc, name, H5T_NATIVE_DOUBLE, [int(nrow, hsize_t), 0_hsize_t], &
         [int(nrow, hsize_t), 1_hsize_t], did, stat, errmsg)
   end subroutine h5io_create_columns

   !> Creates a chunked dataset of element type tid, initial shape dims and
   !> chunks chunk (Fortran order), its last dimension unlimited.
   subroutine create_extendible(loc, name, tid, dims, chunk, did, stat, errmsg)
      integer(hid_t), intent(in) :: loc, tid
      character(len=*), intent(in) :: name
      integer(hsize_t), intent(in) :: dims(:), chunk(:)
      integer(hid_t), intent(out) :: did
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer(hsize_t) :: maxdims(size(dims))
      integer(hid_t) :: sid, plist
      integer :: err, rank

      rank = size(dims)
      maxdims = dims
      maxdims(rank) = H5S_UNLIMITED_F
      did = -1
      call h5screate_simple_f(rank, dims, sid, err, maxdims)
      call h5io_check(err, 'cannot make the dataspace of the dataset', name, stat, errmsg)
      if (stat /= 0) return
      call h5pcreate_f(H5P_DATASET_CREATE_F, plist, err)
      if (err == 0) call h5pset_chunk_f(plist, rank, chunk, err)
      call h5io_check(err, 'cannot set the chunks of the dataset', name, stat, errmsg)
      if (stat == 0) then
         call h5dcreate_f(loc, name, tid, sid, did, err, dcpl_id=plist)
         call h5io_check(err, 'cannot create the dataset', name, stat, errmsg)
      end if
      call h5pclose_f(plist, err)
      call h5sclose_f(sid, err)
   end subroutine create_extendible

   !> Appends the reals x(:) to the rank-1 series did.
   subroutine append_reals(did, x, stat, errmsg)
      integer(hid_t), intent(in) :: did
      real(dp), intent(in) :: x(:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      real(dp), allocatable, target :: buf(:)
      stat = 0
      if (size(x) == 0) return
      buf = x
      call grow_and_write(did, H5T_NATIVE_DOUBLE, 1, size(x), c_loc(buf), stat, errmsg)
   end subroutine append_reals

   !> Appends the integers x(:) to the rank-1 series did.
   subroutine append_integers(did, x, stat, errmsg)
      integer(hid_t), intent(in) :: did
      integer, intent(in) :: x(:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer, allocatable, target :: buf(:)
      stat = 0
      if (size(x) == 0) return
      buf = x
      call grow_and_write(did, H5T_NATIVE_INTEGER, 1, size(x), c_loc(buf), stat, errmsg)
   end subroutine append_integers

   !> Appends the columns x(:, k) (of the dataset's nrow values each) to the
   !> rank-2 series did.
   subroutine append_columns(did, x, stat, errmsg)
      integer(hid_t), intent(in) :: did
      real(dp), intent(in) :: x(:,:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      real(dp), allocatable, target :: buf(:,:)
      stat = 0
      if (size(x, 2) == 0) return
      buf = x
      call grow_and_write(did, H5T_NATIVE_DOUBLE, 2, size(x, 2), c_loc(buf), stat, errmsg)
   end subroutine append_columns

   !> Extends the last dimension of did by n and writes the values at buf
   !> (memory type tid) into the new slices: n values for rank 1, n columns
   !> for rank 2.
   subroutine grow_and_write(did, tid, rank, n, buf, stat, errmsg)
      integer(hid_t), intent(in) :: did, tid
      integer, intent(in) :: rank
      integer, intent(in) :: n
      type(c_ptr), intent(in) :: buf
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer(hsize_t) :: dims(rank), maxdims(rank), start(rank), count(rank)
      integer(hid_t) :: fspace, mspace
      integer :: err

      call h5dget_space_f(did, fspace, err)
      if (err == 0) call h5sget_simple_extent_dims_f(fspace, dims, maxdims, err)
      if (err == rank) err = 0
      if (err == 0) call h5sclose_f(fspace, err)
      call h5io_check(err, 'cannot read the extent of a series', '', stat, errmsg)
      if (stat /= 0) return
      start = 0
      start(rank) = dims(rank)
      count = dims
      count(rank) = int(n, hsize_t)
      dims(rank) = dims(rank) + int(n, hsize_t)
      call h5dset_extent_f(did, dims, err)
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

   !> Creates `name`, a virtual dataset (HDF5 1.10's VDS) of nrow reals
   !> that shows column `column` (from 1) of the rank-2 series `source`
   !> (h5io_create_columns) of the same file: a view, no copy. A reader sees
   !> a plain 1-D dataset (h5py, h5dump, XDMF readers); `source` needs at
   !> least `column` columns when the view is read.
   subroutine h5io_view_column(loc, name, source, nrow, column, stat, errmsg)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name, source
      integer, intent(in) :: nrow, column
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer(hid_t) :: vspace, sspace, plist, did
      integer :: err
      !> The file a virtual dataset's source is in: '.', the same file.
      character(len=*), parameter :: same_file = '.'

      call h5screate_simple_f(1, [int(nrow, hsize_t)], vspace, err)
      call h5io_check(err, 'cannot make the dataspace of the view', name, stat, errmsg)
      if (stat /= 0) return
      call h5screate_simple_f(2, [int(nrow, hsize_t), int(column, hsize_t)], sspace, err, &
         [int(nrow, hsize_t), H5S_UNLIMITED_F])
      if (err == 0) call h5sselect_hyperslab_f(sspace, H5S_SELECT_SET_F, [0_hsize_t, int(column - 1, hsize_t)], &
         [int(nrow, hsize_t), 1_hsize_t], err)
      if (err == 0) call h5pcreate_f(H5P_DATASET_CREATE_F, plist, err)
      if (err == 0) call h5pset_virtual_f(plist, vspace, same_file, source, sspace, err)
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

   !> Closes a dataset opened by h5io_create_series or h5io_create_columns.
   subroutine h5io_close_dataset(did, stat, errmsg)
      integer(hid_t), intent(in) :: did
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer :: err
      call h5dclose_f(did, err)
      call h5io_check(err, 'cannot close a dataset', '', stat, errmsg)
   end subroutine h5io_close_dataset

   ! ------------------------------------------------------------ messages

   !> stat = 0 if HDF5's error code err is 0, else failed and the message
   !> "what 'name'" (name '' for none).
   subroutine h5io_check(err, what, name, stat, errmsg)
      integer, intent(in) :: err
      character(len=*), intent(in) :: what, name
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      if (err == 0) then
         stat = 0
      else
         call h5io_fail(what, name, stat, errmsg)
      end if
   end subroutine h5io_check

   !> stat = failed and the message "what 'name'" (or "what" without a name).
   subroutine h5io_fail(what, name, stat, errmsg)
      character(len=*), intent(in) :: what, name
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      stat = failed
      if (len(name) > 0) then
         errmsg = what//" '"//name//"'"
      else
         errmsg = what
      end if
   end subroutine h5io_fail

   !> 'obj@name' for messages about attribute name of object obj.
   pure function h5io_attr_path(obj, name) result(text)
      character(len=*), intent(in) :: obj, name
      character(len=len(obj) + len(name) + 1) :: text
      text = obj//'@'//name
   end function h5io_attr_path

end module hdf5_io
