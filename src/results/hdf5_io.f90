!> Thin checked wrappers over HDF5-Fortran for the results files: files, groups, attributes, whole
!> datasets (the growing ones: hdf5_series.f90). Every routine returns `stat` (0 on success) and an
!> `errmsg` naming the operation and the object; `loc` is the file or group a path starts from,
!> `name` a path relative to it. Attributes are scalars or 1-D arrays, strings variable-length
!> UTF-8; every dataset chunked and checksummed (Fletcher32), in Fortran order (x(m, n) reads as
!> x[n, m] in h5py). tools/hdf5_read.f90 is the read half. Not from the paper. More: docs/OUTPUT.md.
module hdf5_io
   use, intrinsic :: iso_c_binding, only: c_ptr, c_loc, c_char, c_null_char, c_bool, c_int, c_int64_t
   use hdf5, only: hid_t, hsize_t, size_t, h5open_f, h5eset_auto_f, h5fcreate_f, h5fopen_f, h5fclose_f, &
      h5fflush_f, H5F_ACC_EXCL_F, H5F_ACC_RDWR_F, H5F_SCOPE_GLOBAL_F, H5F_LIBVER_LATEST_F, h5gcreate_f, &
      h5gclose_f, h5ldelete_f, h5lexists_f, h5oopen_f, h5oclose_f, h5screate_f, h5screate_simple_f, h5sclose_f, &
      H5S_SCALAR_F, H5S_UNLIMITED_F, h5acreate_by_name_f, h5aopen_f, h5awrite_f, h5aclose_f, h5aexists_by_name_f, &
      h5adelete_by_name_f, h5tcopy_f, h5tset_size_f, h5tset_cset_f, h5tclose_f, H5T_NATIVE_DOUBLE, &
      H5T_NATIVE_INTEGER, H5T_FORTRAN_S1, H5T_CSET_UTF8_F, h5tset_strpad_f, H5T_STR_NULLTERM_F, h5pcreate_f, &
      h5pset_chunk_f, h5pset_fletcher32_f, h5pset_libver_bounds_f, h5pset_file_locking_f, h5pclose_f, &
      H5P_DATASET_CREATE_F, H5P_FILE_ACCESS_F, h5dcreate_f, h5dopen_f, h5dclose_f, h5dwrite_f
   use kinds, only: dp
   use file_system, only: remove_file
   implicit none
   private
   public :: h5io_start, h5io_open, h5io_close, h5io_flush, h5io_group, h5io_delete
   public :: h5io_set_attr, h5io_update_attr, h5io_write, h5io_rewrite
   public :: h5io_check, h5io_fail, h5io_attr_path, h5io_vlen_string_type
   public :: h5io_create_dataset
   !> Status returned on any failure.
   integer, parameter :: failed = 1
   !> The size of a variable-length string type: HDF5's H5T_VARIABLE,
   !> (size_t)(-1) in C, which the HDF5 1.10 Fortran module does not define.
   integer(size_t), parameter :: variable_length = -1_size_t
   !> H5F_ACC_SWMR_WRITE (<H5Fpublic.h>, 0x0020), which the HDF5 1.10 Fortran
   !> module does not define; h5fopen_f hands its flags to H5Fopen as they are.
   integer, parameter :: acc_swmr_write = 32

   !> Writes an attribute: a real(dp), integer or string scalar, or a real(dp) or integer 1-D array.
   interface h5io_set_attr
      module procedure set_attr_scalar, set_attr_array
   end interface h5io_set_attr

   !> Writes a whole dataset, one checksummed chunk: real(dp) or integer, rank 1 or 2.
   interface h5io_write
      module procedure write_1d, write_2d
   end interface h5io_write

contains

   !> Opens the HDF5 library and switches off its error printing.
   subroutine h5io_start(stat, errmsg)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer :: err
      call h5open_f(err)
      if (err == 0) call h5eset_auto_f(0, err)
      call h5io_check(err, 'cannot initialise the HDF5 library', '', stat, errmsg)
   end subroutine h5io_start

   !> With `create`, creates the file `path` exclusively (what had the name removed first: no write
   !> through a link), with `swmr` in HDF5 1.10's format (what SWMR needs); else opens the existing
   !> file for writing, with `swmr` in SWMR mode, clearing the marks a killed writer left (what
   !> `h5clear -s` does).
   subroutine h5io_open(path, create, swmr, fid, stat, errmsg)
      character(len=*), intent(in) :: path
      logical, intent(in) :: create, swmr
      integer(hid_t), intent(out) :: fid
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer :: err
      integer(hid_t) :: fapl
      fid = -1
      call file_access(swmr .or. .not. create, .not. create, fapl, err)
      call h5io_check(err, 'cannot set up the access to the HDF5 file', path, stat, errmsg)
      if (stat /= 0) return
      if (create) then
         call remove_file(path, err)
         call h5fcreate_f(path, H5F_ACC_EXCL_F, fid, err, access_prp=fapl)
         call h5io_check(err, 'cannot create the HDF5 file', path, stat, errmsg)
      else
         call h5fopen_f(path, merge(ior(H5F_ACC_RDWR_F, acc_swmr_write), H5F_ACC_RDWR_F, swmr), fid, &
            err, access_prp=fapl)
         call h5io_check(err, 'cannot open the HDF5 file for writing', path, stat, errmsg)
      end if
      call h5pclose_f(fapl, err)
   end subroutine h5io_open

   !> The results files' access: no file lock (runs keep apart by their claim),
   !> metadata evicted on close (the XDMF views would fill the cache), `latest`
   !> format; with `clear` a killed writer's marks cleared on opening.
   subroutine file_access(latest, clear, fapl, err)
      logical, intent(in) :: latest, clear
      integer(hid_t), intent(out) :: fapl
      integer, intent(out) :: err
      logical(c_bool), target :: yes
      interface
         !> herr_t H5Pset_evict_on_close(hid_t fapl_id, hbool_t evict_on_close); hbool_t is C's bool
         function c_h5pset_evict_on_close(fapl_id, evict) bind(c, name='H5Pset_evict_on_close') result(r)
            import :: c_int64_t, c_bool, c_int
            integer(c_int64_t), value :: fapl_id     ! hid_t: int64_t since HDF5 1.10
            logical(c_bool), value :: evict
            integer(c_int) :: r
         end function c_h5pset_evict_on_close
         !> herr_t H5Pset(hid_t plist_id, const char *name, const void *value)
         function c_h5pset(plist_id, name, value) bind(c, name='H5Pset') result(r)
            import :: c_int64_t, c_char, c_ptr, c_int
            integer(c_int64_t), value :: plist_id
            character(kind=c_char), intent(in) :: name(*)
            type(c_ptr), value :: value
            integer(c_int) :: r
         end function c_h5pset
      end interface
      yes = .true.
      call h5pcreate_f(H5P_FILE_ACCESS_F, fapl, err)
      if (err == 0) err = int(c_h5pset_evict_on_close(int(fapl, c_int64_t), yes))
      if (err == 0) call h5pset_file_locking_f(fapl, .false., .true., err)
      if (err == 0 .and. latest) call h5pset_libver_bounds_f(fapl, H5F_LIBVER_LATEST_F, H5F_LIBVER_LATEST_F, err)
      if (err == 0 .and. clear) err = int(c_h5pset(int(fapl, c_int64_t), 'clear_status_flags' // c_null_char, &
         c_loc(yes)))
   end subroutine file_access

   !> Closes the file fid.
   subroutine h5io_close(fid, stat, errmsg)
      integer(hid_t), intent(in) :: fid
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer :: err
      call h5fclose_f(fid, err)
      call h5io_check(err, 'cannot close the HDF5 file', '', stat, errmsg)
   end subroutine h5io_close

   !> Writes everything buffered to the file (H5Fflush): a later kill leaves it whole.
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

   !> Removes the link `name` when there is one (the object goes with its last link).
   subroutine h5io_delete(loc, name, stat, errmsg)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      logical :: there
      integer :: err
      stat = 0
      call h5lexists_f(loc, name, there, err)
      if (err /= 0 .or. .not. there) return
      call h5ldelete_f(loc, name, err)
      call h5io_check(err, 'cannot remove', name, stat, errmsg)
   end subroutine h5io_delete

   !> Scalar attribute `name` of object `obj`: real(dp), integer or a string.
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

   !> 1-D array attribute `name` of object `obj` (one value at least): real(dp) or integer.
   subroutine set_attr_array(loc, obj, name, x, stat, errmsg)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: obj, name
      class(*), intent(in), target, contiguous :: x(:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      select type (x)
      type is (real(dp))
         call put_attr(loc, obj, name, H5T_NATIVE_DOUBLE, c_loc(x), size(x), stat, errmsg)
      type is (integer)
         call put_attr(loc, obj, name, H5T_NATIVE_INTEGER, c_loc(x), size(x), stat, errmsg)
      class default
         call h5io_fail('an array attribute is real(dp) or integer', h5io_attr_path(obj, name), stat, errmsg)
      end select
   end subroutine set_attr_array

   !> Rewrites the existing real(dp) or integer scalar attribute `name` of `obj`
   !> in place: what SWMR mode allows.
   subroutine h5io_update_attr(loc, obj, name, x, stat, errmsg)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: obj, name
      class(*), intent(in), target :: x
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer(hid_t) :: oid, aid
      integer :: err
      ! the object held open while its attribute is written (evict-on-close)
      call h5oopen_f(loc, obj, oid, err)
      if (err == 0) call h5aopen_f(oid, name, aid, err)
      call h5io_check(err, 'cannot open the attribute', h5io_attr_path(obj, name), stat, errmsg)
      if (stat /= 0) then
         call h5oclose_f(oid, err)
         return
      end if
      err = -1
      select type (x)
      type is (real(dp))
         call h5awrite_f(aid, H5T_NATIVE_DOUBLE, c_loc(x), err)
      type is (integer)
         call h5awrite_f(aid, H5T_NATIVE_INTEGER, c_loc(x), err)
      end select
      call h5io_check(err, 'cannot rewrite the attribute', h5io_attr_path(obj, name), stat, errmsg)
      call h5aclose_f(aid, err)
      call h5oclose_f(oid, err)
   end subroutine h5io_update_attr

   !> Creates (or replaces) attribute `name` of type tid from buf: a scalar when n = 0, else n values.
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

   !> A variable-length, null-terminated UTF-8 string type (the caller closes it),
   !> from H5T_FORTRAN_S1 (HDF5 1.10's H5T_STRING cannot be resized).
   subroutine h5io_vlen_string_type(tid, err)
      integer(hid_t), intent(out) :: tid  !< the new type
      integer, intent(out) :: err         !< HDF5's error code (0 on success)
      call h5tcopy_f(H5T_FORTRAN_S1, tid, err)
      if (err == 0) call h5tset_size_f(tid, variable_length, err)
      if (err == 0) call h5tset_strpad_f(tid, H5T_STR_NULLTERM_F, err)
      if (err == 0) call h5tset_cset_f(tid, H5T_CSET_UTF8_F, err)
   end subroutine h5io_vlen_string_type

   !> Writes the dataset `name` of the 2-D array x, real(dp) or integer.
   subroutine write_2d(loc, name, x, stat, errmsg)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      class(*), intent(in) :: x(:,:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      stat = 1
      select type (x)
      type is (real(dp))
         call write_1d(loc, name, reshape(x, [size(x)]), stat, errmsg, shape(x, kind=hsize_t))
      type is (integer)
         call write_1d(loc, name, reshape(x, [size(x)]), stat, errmsg, shape(x, kind=hsize_t))
      end select
   end subroutine write_2d

   !> Writes the dataset `name` of the 1-D array x, real(dp) or integer, one chunk; of shape `shp`
   !> when given (write_2d: x in Fortran order).
   subroutine write_1d(loc, name, x, stat, errmsg, shp)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      class(*), intent(in), target, contiguous :: x(:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer(hsize_t), intent(in), optional :: shp(:)
      integer(hsize_t), allocatable :: dims(:)
      integer(hid_t) :: did
      integer :: err
      stat = failed
      allocate (dims, source=shape(x, kind=hsize_t))
      if (present(shp)) dims = shp
      select type (x)
      type is (real(dp))
         call h5io_create_dataset(loc, name, H5T_NATIVE_DOUBLE, dims, max(dims, 1_hsize_t), did, stat, errmsg)
         if (stat == 0) call h5dwrite_f(did, H5T_NATIVE_DOUBLE, c_loc(x), err)
      type is (integer)
         call h5io_create_dataset(loc, name, H5T_NATIVE_INTEGER, dims, max(dims, 1_hsize_t), did, stat, errmsg)
         if (stat == 0) call h5dwrite_f(did, H5T_NATIVE_INTEGER, c_loc(x), err)
      end select
      if (stat /= 0) return
      call h5io_check(err, 'cannot write the dataset', name, stat, errmsg)
      call h5dclose_f(did, err)
   end subroutine write_1d

   !> Overwrites the whole existing real dataset `name` with x(:), of its size.
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

   !> Creates the dataset `name` of type tid, largest shape maxdims (an unlimited
   !> dimension starts empty), in checksummed chunks of shape chunk; open as did.
   subroutine h5io_create_dataset(loc, name, tid, maxdims, chunk, did, stat, errmsg)
      integer(hid_t), intent(in) :: loc, tid
      character(len=*), intent(in) :: name
      integer(hsize_t), intent(in) :: maxdims(:), chunk(:)
      integer(hid_t), intent(out) :: did
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer(hsize_t) :: dims(size(maxdims))
      integer(hid_t) :: sid, plist
      integer :: err
      did = -1
      dims = merge(0_hsize_t, maxdims, maxdims == H5S_UNLIMITED_F)
      call h5screate_simple_f(size(dims), dims, sid, err, maxdims)
      call h5io_check(err, 'cannot make the dataspace of the dataset', name, stat, errmsg)
      if (stat /= 0) return
      call h5pcreate_f(H5P_DATASET_CREATE_F, plist, err)
      if (err == 0) call h5pset_chunk_f(plist, size(chunk), chunk, err)
      if (err == 0) call h5pset_fletcher32_f(plist, err)
      call h5io_check(err, 'cannot set the chunks and checksums of the dataset', name, stat, errmsg)
      if (stat == 0) then
         call h5dcreate_f(loc, name, tid, sid, did, err, dcpl_id=plist)
         call h5io_check(err, 'cannot create the dataset', name, stat, errmsg)
      end if
      call h5pclose_f(plist, err)
      call h5sclose_f(sid, err)
   end subroutine h5io_create_dataset

   !> stat = 0 if HDF5's error code err is 0, else as h5io_fail.
   subroutine h5io_check(err, what, name, stat, errmsg)
      integer, intent(in) :: err
      character(len=*), intent(in) :: what, name
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      stat = 0
      if (err /= 0) call h5io_fail(what, name, stat, errmsg)
   end subroutine h5io_check

   !> stat = failed and the message "what 'name'" (or "what" without a name).
   subroutine h5io_fail(what, name, stat, errmsg)
      character(len=*), intent(in) :: what, name
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      stat = failed
      errmsg = what
      if (len(name) > 0) errmsg = what//" '"//name//"'"
   end subroutine h5io_fail

   !> 'obj@name' for messages about attribute name of object obj.
   pure function h5io_attr_path(obj, name) result(text)
      character(len=*), intent(in) :: obj, name
      character(len=len(obj) + len(name) + 1) :: text
      text = obj//'@'//name
   end function h5io_attr_path

end module hdf5_io
