!> Thin checked wrappers over HDF5-Fortran for the results file
!> (src/results_hdf5.f90) and the tools that read it (tools/h5export.f90).
!>
!> Every routine returns `stat` (0 on success) and a message naming the
!> operation and the object; the library's own error printing is switched
!> off by h5io_start, so a failure reads as one line of the caller's.
!>
!> What is written, and how a reader sees it:
!>  - attributes are scalars (dataspace SCALAR: h5py gives a number or a
!>    str, not a one-element array), or 1-D arrays (h5io_set_attr with an
!>    array); strings are variable-length UTF-8 (h5py gives str);
!>  - fixed datasets are written whole with the high-level H5LT calls;
!>  - series are extendible chunked datasets that grow by one entry per
!>    h5io_append: rank 1 (n) for a history column, rank 2 (nrow, n) in
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
   use, intrinsic :: iso_c_binding, only: c_ptr, c_loc, c_f_pointer, c_char, c_null_char
   use hdf5, only: hid_t, hsize_t, size_t, h5open_f, h5eset_auto_f, h5fcreate_f, h5fopen_f, h5fclose_f, &
      h5fflush_f, H5F_ACC_TRUNC_F, H5F_ACC_RDONLY_F, H5F_SCOPE_GLOBAL_F, h5gcreate_f, h5gclose_f, &
      h5screate_f, h5screate_simple_f, h5sclose_f, h5sselect_hyperslab_f, h5sget_simple_extent_dims_f, &
      H5S_SCALAR_F, H5S_UNLIMITED_F, H5S_SELECT_SET_F, &
      h5acreate_by_name_f, h5aopen_by_name_f, h5awrite_f, h5aread_f, h5aclose_f, h5aexists_by_name_f, &
      h5adelete_by_name_f, h5aget_type_f, h5aget_space_f, &
      h5tcopy_f, h5tset_size_f, h5tget_size_f, h5tset_cset_f, h5tclose_f, h5tis_variable_str_f, &
      H5T_NATIVE_DOUBLE, H5T_NATIVE_INTEGER, H5T_FORTRAN_S1, H5T_CSET_UTF8_F, h5tset_strpad_f, &
      H5T_STR_NULLTERM_F, &
      h5pcreate_f, h5pset_chunk_f, h5pclose_f, H5P_DATASET_CREATE_F, H5P_DEFAULT_F, &
      h5dcreate_f, h5dopen_f, h5dclose_f, h5dwrite_f, h5dset_extent_f, h5dget_space_f, h5dvlen_reclaim_f
   use h5lt, only: h5ltmake_dataset_double_f, h5ltmake_dataset_int_f, h5ltread_dataset_double_f, &
      h5ltread_dataset_int_f, h5ltget_dataset_ndims_f, h5ltget_dataset_info_f
   use kinds, only: dp, msg_len
   implicit none
   private
   public :: h5io_start, h5io_create, h5io_close, h5io_flush, h5io_group
   public :: h5io_set_attr, h5io_write, h5io_rewrite
   public :: h5io_check, h5io_fail, h5io_attr_path, h5io_vlen_string_type
   public :: h5io_create_series, h5io_create_columns, h5io_append, h5io_close_dataset
   public :: h5io_real, h5io_integer

   !> Element types of a series (h5io_create_series).
   integer, parameter :: h5io_real = 1, h5io_integer = 2
   !> Status returned on any failure.
   integer, parameter :: failed = 1
   !> The size of a variable-length string type: HDF5's H5T_VARIABLE,
   !> (size_t)(-1) in C, which the HDF5 1.10 Fortran module does not define.
   integer(size_t), parameter :: variable_length = -1_size_t

   !> Writes an attribute: real, integer or string scalar, real or integer array.
   interface h5io_set_attr
      module procedure set_attr_real, set_attr_int, set_attr_string, set_attr_real_1d, set_attr_int_1d
   end interface h5io_set_attr

   !> Reads a scalar attribute: real, integer or string (fixed or variable length).

   !> Writes a whole dataset (H5LT): real or integer, rank 1 or 2.
   interface h5io_write
      module procedure write_real_1d, write_real_2d, write_int_1d, write_int_2d
   end interface h5io_write

   !> Reads a whole dataset (H5LT) into an allocatable array of its shape.

   !> Appends one entry to a series: a real or an integer to a rank-1 series,
   !> a real column to a rank-2 series.
   interface h5io_append
      module procedure append_real, append_int, append_column
   end interface h5io_append

contains

   ! ------------------------------------------------------------ files, groups

   !> Opens the HDF5 library (its predefined types) and switches off its own
   !> error printing. Safe to call more than once.
   subroutine h5io_start(stat, errmsg)
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer :: err
      call h5open_f(err)
      if (err /= 0) then
         call h5io_fail('cannot initialise the HDF5 library', '', stat, errmsg)
         return
      end if
      call h5eset_auto_f(0, err)
      stat = 0
   end subroutine h5io_start

   !> Creates (or truncates) the file `path` for writing.
   subroutine h5io_create(path, fid, stat, errmsg)
      !> File path.
      character(len=*), intent(in) :: path
      !> Id of the open file.
      integer(hid_t), intent(out) :: fid
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer :: err
      call h5fcreate_f(path, H5F_ACC_TRUNC_F, fid, err)
      call h5io_check(err, 'cannot create the HDF5 file', path, stat, errmsg)
   end subroutine h5io_create


   !> Closes a file.
   subroutine h5io_close(fid, stat, errmsg)
      !> Id of the open file.
      integer(hid_t), intent(in) :: fid
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer :: err
      call h5fclose_f(fid, err)
      call h5io_check(err, 'cannot close the HDF5 file', '', stat, errmsg)
   end subroutine h5io_close

   !> Writes everything buffered to the file (H5Fflush), so that a run killed
   !> later leaves a file that opens with all it had written so far.
   subroutine h5io_flush(fid, stat, errmsg)
      !> Id of the open file.
      integer(hid_t), intent(in) :: fid
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer :: err
      call h5fflush_f(fid, H5F_SCOPE_GLOBAL_F, err)
      call h5io_check(err, 'cannot flush the HDF5 file', '', stat, errmsg)
   end subroutine h5io_flush

   !> Creates the group `name` (a path relative to loc; its parent must exist).
   subroutine h5io_group(loc, name, stat, errmsg)
      !> File or group the path starts from.
      integer(hid_t), intent(in) :: loc
      !> Group path.
      character(len=*), intent(in) :: name
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
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

   !> Real scalar attribute `name` of object `obj`.
   subroutine set_attr_real(loc, obj, name, x, stat, errmsg)
      !> File or group the object path starts from.
      integer(hid_t), intent(in) :: loc
      !> Object path ('.' for loc itself) and attribute name.
      character(len=*), intent(in) :: obj, name
      !> Value.
      real(dp), intent(in), target :: x
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      call put_attr(loc, obj, name, H5T_NATIVE_DOUBLE, c_loc(x), 0, stat, errmsg)
   end subroutine set_attr_real

   !> Integer scalar attribute `name` of object `obj`.
   subroutine set_attr_int(loc, obj, name, i, stat, errmsg)
      !> File or group the object path starts from.
      integer(hid_t), intent(in) :: loc
      !> Object path ('.' for loc itself) and attribute name.
      character(len=*), intent(in) :: obj, name
      !> Value.
      integer, intent(in), target :: i
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      call put_attr(loc, obj, name, H5T_NATIVE_INTEGER, c_loc(i), 0, stat, errmsg)
   end subroutine set_attr_int

   !> Real 1-D array attribute `name` of object `obj`.
   subroutine set_attr_real_1d(loc, obj, name, x, stat, errmsg)
      !> File or group the object path starts from.
      integer(hid_t), intent(in) :: loc
      !> Object path ('.' for loc itself) and attribute name.
      character(len=*), intent(in) :: obj, name
      !> Values (at least one).
      real(dp), intent(in), target :: x(:)
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      real(dp), target :: buf(size(x))
      buf = x
      call put_attr(loc, obj, name, H5T_NATIVE_DOUBLE, c_loc(buf), size(buf), stat, errmsg)
   end subroutine set_attr_real_1d

   !> Integer 1-D array attribute `name` of object `obj`.
   subroutine set_attr_int_1d(loc, obj, name, i, stat, errmsg)
      !> File or group the object path starts from.
      integer(hid_t), intent(in) :: loc
      !> Object path ('.' for loc itself) and attribute name.
      character(len=*), intent(in) :: obj, name
      !> Values (at least one).
      integer, intent(in), target :: i(:)
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer, target :: buf(size(i))
      buf = i
      call put_attr(loc, obj, name, H5T_NATIVE_INTEGER, c_loc(buf), size(buf), stat, errmsg)
   end subroutine set_attr_int_1d

   !> String attribute `name` of object `obj`: variable-length UTF-8, trailing
   !> blanks removed.
   subroutine set_attr_string(loc, obj, name, s, stat, errmsg)
      !> File or group the object path starts from.
      integer(hid_t), intent(in) :: loc
      !> Object path ('.' for loc itself) and attribute name.
      character(len=*), intent(in) :: obj, name
      !> Value.
      character(len=*), intent(in) :: s
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      character(kind=c_char), allocatable, target :: chars(:)
      type(c_ptr), target :: ptr(1)
      integer(hid_t) :: tid
      integer :: err, k, n

      n = len_trim(s)
      allocate (chars(n + 1))
      do k = 1, n
         chars(k) = s(k:k)
      end do
      chars(n + 1) = c_null_char
      ptr(1) = c_loc(chars)
      call h5io_vlen_string_type(tid, err)
      call h5io_check(err, 'cannot make a string type for the attribute', name, stat, errmsg)
      if (stat /= 0) return
      call put_attr(loc, obj, name, tid, c_loc(ptr), 0, stat, errmsg)
      call h5tclose_f(tid, err)
   end subroutine set_attr_string

   !> Creates (replacing one of the same name) and writes an attribute of
   !> type tid: a scalar when n = 0, else a 1-D array of n values.
   subroutine put_attr(loc, obj, name, tid, buf, n, stat, errmsg)
      !> File or group the object path starts from; memory and file type of the value.
      integer(hid_t), intent(in) :: loc, tid
      !> Object path and attribute name.
      character(len=*), intent(in) :: obj, name
      !> Address of the value(s).
      type(c_ptr), intent(in) :: buf
      !> 0 for a scalar, else the number of values.
      integer, intent(in) :: n
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
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
      !> The new type.
      integer(hid_t), intent(out) :: tid
      !> HDF5's error code (0 on success).
      integer, intent(out) :: err
      call h5tcopy_f(H5T_FORTRAN_S1, tid, err)
      if (err == 0) call h5tset_size_f(tid, variable_length, err)
      if (err == 0) call h5tset_strpad_f(tid, H5T_STR_NULLTERM_F, err)
      if (err == 0) call h5tset_cset_f(tid, H5T_CSET_UTF8_F, err)
   end subroutine h5io_vlen_string_type

   ! ------------------------------------------------------------ whole datasets

   !> Writes the real dataset `name` of x(:).
   subroutine write_real_1d(loc, name, x, stat, errmsg)
      !> File or group the path starts from.
      integer(hid_t), intent(in) :: loc
      !> Dataset path.
      character(len=*), intent(in) :: name
      !> Values.
      real(dp), intent(in) :: x(:)
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer :: err
      call h5ltmake_dataset_double_f(loc, name, 1, shape(x, kind=hsize_t), x, err)
      call h5io_check(err, 'cannot write the dataset', name, stat, errmsg)
   end subroutine write_real_1d

   !> Writes the real dataset `name` of x(:,:) (C order: x[n2, n1]).
   subroutine write_real_2d(loc, name, x, stat, errmsg)
      !> File or group the path starts from.
      integer(hid_t), intent(in) :: loc
      !> Dataset path.
      character(len=*), intent(in) :: name
      !> Values.
      real(dp), intent(in) :: x(:,:)
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer :: err
      call h5ltmake_dataset_double_f(loc, name, 2, shape(x, kind=hsize_t), x, err)
      call h5io_check(err, 'cannot write the dataset', name, stat, errmsg)
   end subroutine write_real_2d

   !> Writes the integer dataset `name` of i(:).
   subroutine write_int_1d(loc, name, i, stat, errmsg)
      !> File or group the path starts from.
      integer(hid_t), intent(in) :: loc
      !> Dataset path.
      character(len=*), intent(in) :: name
      !> Values.
      integer, intent(in) :: i(:)
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer :: err
      call h5ltmake_dataset_int_f(loc, name, 1, shape(i, kind=hsize_t), i, err)
      call h5io_check(err, 'cannot write the dataset', name, stat, errmsg)
   end subroutine write_int_1d

   !> Writes the integer dataset `name` of i(:,:) (C order: i[n2, n1]).
   subroutine write_int_2d(loc, name, i, stat, errmsg)
      !> File or group the path starts from.
      integer(hid_t), intent(in) :: loc
      !> Dataset path.
      character(len=*), intent(in) :: name
      !> Values.
      integer, intent(in) :: i(:,:)
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer :: err
      call h5ltmake_dataset_int_f(loc, name, 2, shape(i, kind=hsize_t), i, err)
      call h5io_check(err, 'cannot write the dataset', name, stat, errmsg)
   end subroutine write_int_2d

   !> Overwrites the whole existing real dataset `name` with x(:), which must
   !> have its size.
   subroutine h5io_rewrite(loc, name, x, stat, errmsg)
      !> File or group the path starts from.
      integer(hid_t), intent(in) :: loc
      !> Dataset path.
      character(len=*), intent(in) :: name
      !> Values.
      real(dp), intent(in) :: x(:)
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
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
   !> and returns it open.
   subroutine h5io_create_series(loc, name, kind, chunk, did, stat, errmsg)
      !> File or group the path starts from.
      integer(hid_t), intent(in) :: loc
      !> Dataset path.
      character(len=*), intent(in) :: name
      !> h5io_real or h5io_integer.
      integer, intent(in) :: kind
      !> Entries per chunk (>= 1).
      integer, intent(in) :: chunk
      !> Id of the open dataset (close with h5io_close_dataset).
      integer(hid_t), intent(out) :: did
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer(hid_t) :: tid
      if (kind == h5io_integer) then
         tid = H5T_NATIVE_INTEGER
      else
         tid = H5T_NATIVE_DOUBLE
      end if
      call create_extendible(loc, name, tid, [0_hsize_t], [int(chunk, hsize_t)], did, stat, errmsg)
   end subroutine h5io_create_series

   !> Creates the empty extendible real dataset `name` of shape (nrow, 0),
   !> growing by whole columns of nrow values (one chunk each), and returns it open.
   subroutine h5io_create_columns(loc, name, nrow, did, stat, errmsg)
      !> File or group the path starts from.
      integer(hid_t), intent(in) :: loc
      !> Dataset path.
      character(len=*), intent(in) :: name
      !> Values per column (>= 1).
      integer, intent(in) :: nrow
      !> Id of the open dataset (close with h5io_close_dataset).
      integer(hid_t), intent(out) :: did
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      call create_extendible(loc, name, H5T_NATIVE_DOUBLE, [int(nrow, hsize_t), 0_hsize_t], &
         [int(nrow, hsize_t), 1_hsize_t], did, stat, errmsg)
   end subroutine h5io_create_columns

   !> Creates a chunked dataset of initial shape dims whose last dimension is unlimited.
   subroutine create_extendible(loc, name, tid, dims, chunk, did, stat, errmsg)
      !> File or group the path starts from; element type.
      integer(hid_t), intent(in) :: loc, tid
      !> Dataset path.
      character(len=*), intent(in) :: name
      !> Initial dimensions and chunk dimensions, Fortran order.
      integer(hsize_t), intent(in) :: dims(:), chunk(:)
      !> Id of the open dataset.
      integer(hid_t), intent(out) :: did
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
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

   !> Appends the real x to the rank-1 series did.
   subroutine append_real(did, x, stat, errmsg)
      !> Open extendible dataset.
      integer(hid_t), intent(in) :: did
      !> Value.
      real(dp), intent(in), target :: x
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      call grow_and_write(did, H5T_NATIVE_DOUBLE, 1, c_loc(x), stat, errmsg)
   end subroutine append_real

   !> Appends the integer i to the rank-1 series did.
   subroutine append_int(did, i, stat, errmsg)
      !> Open extendible dataset.
      integer(hid_t), intent(in) :: did
      !> Value.
      integer, intent(in), target :: i
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      call grow_and_write(did, H5T_NATIVE_INTEGER, 1, c_loc(i), stat, errmsg)
   end subroutine append_int

   !> Appends the column x(:) (its size the dataset's nrow) to the rank-2 series did.
   subroutine append_column(did, x, stat, errmsg)
      !> Open extendible dataset.
      integer(hid_t), intent(in) :: did
      !> Values.
      real(dp), intent(in) :: x(:)
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      real(dp), target :: buf(size(x))
      buf = x
      call grow_and_write(did, H5T_NATIVE_DOUBLE, 2, c_loc(buf), stat, errmsg)
   end subroutine append_column

   !> Extends the last dimension of did by one and writes buf into the new
   !> slice (one value for rank 1, one column for rank 2).
   subroutine grow_and_write(did, tid, rank, buf, stat, errmsg)
      !> Open extendible dataset; memory type of the values.
      integer(hid_t), intent(in) :: did, tid
      !> Rank of the dataset (1 or 2).
      integer, intent(in) :: rank
      !> Address of the new value or column.
      type(c_ptr), intent(in) :: buf
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
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
      count(rank) = 1
      dims(rank) = dims(rank) + 1
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

   !> Closes a dataset opened by h5io_create_series or h5io_create_columns.
   subroutine h5io_close_dataset(did, stat, errmsg)
      !> Open dataset.
      integer(hid_t), intent(in) :: did
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer :: err
      call h5dclose_f(did, err)
      call h5io_check(err, 'cannot close a dataset', '', stat, errmsg)
   end subroutine h5io_close_dataset

   ! ------------------------------------------------------------ messages

   !> stat = 0 if err = 0, else failed and the message "what 'name'".
   subroutine h5io_check(err, what, name, stat, errmsg)
      !> HDF5's error code.
      integer, intent(in) :: err
      !> What failed, and the object it failed on ('' for none).
      character(len=*), intent(in) :: what, name
      !> 0, or failed.
      integer, intent(out) :: stat
      !> Set on failure.
      character(len=*), intent(inout) :: errmsg
      if (err == 0) then
         stat = 0
      else
         call h5io_fail(what, name, stat, errmsg)
      end if
   end subroutine h5io_check

   !> stat = failed and the message "what 'name'" (or "what" without a name).
   subroutine h5io_fail(what, name, stat, errmsg)
      !> What failed, and the object it failed on ('' for none).
      character(len=*), intent(in) :: what, name
      !> Set to failed.
      integer, intent(out) :: stat
      !> The message.
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
      !> Object path and attribute name.
      character(len=*), intent(in) :: obj, name
      character(len=len(obj) + len(name) + 1) :: text
      text = obj//'@'//name
   end function h5io_attr_path

end module hdf5_io
