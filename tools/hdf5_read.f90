!> The read half of the checked HDF5 wrappers (src/results/hdf5_io.f90 has the
!> write half the program uses): what the tools that read a results file
!> <prefix>.h5 need, tools/h5export.f90 and the tests. Every routine
!> returns stat (0 on success) and a message naming the object.
module hdf5_read
   use, intrinsic :: iso_c_binding, only: c_ptr, c_loc, c_f_pointer, c_char, c_null_char
   use hdf5, only: hid_t, hsize_t, size_t, h5fopen_f, H5F_ACC_RDONLY_F, h5aopen_by_name_f, h5aread_f, &
      h5aclose_f, h5aget_type_f, h5aget_space_f, h5sclose_f, h5tcopy_f, h5tset_size_f, h5tget_size_f, &
      h5tclose_f, h5tis_variable_str_f, H5T_NATIVE_DOUBLE, H5T_NATIVE_INTEGER, H5T_FORTRAN_S1, &
      H5P_DEFAULT_F, h5dvlen_reclaim_f
   use h5lt, only: h5ltread_dataset_double_f, h5ltread_dataset_int_f, h5ltget_dataset_ndims_f, &
      h5ltget_dataset_info_f
   use kinds, only: dp
   use hdf5_io, only: h5io_check, h5io_fail, h5io_attr_path, h5io_vlen_string_type
   implicit none
   private
   public :: h5io_open_read, h5io_get_attr, h5io_read

   !> Reads an attribute: real, integer or string scalar.
   interface h5io_get_attr
      module procedure get_attr_real, get_attr_int, get_attr_string
   end interface h5io_get_attr

   !> What a failed read of a dataset says: HDF5 checks the Fletcher32
   !> checksum of a dataset written with one, and the structure of the file.
   character(len=*), parameter :: read_error = 'HDF5 reports an error reading the data (a checksum that does not ' &
      // 'match, or a damaged file) of the dataset'

   !> Reads a whole dataset: real or integer, rank 1 or 2.
   interface h5io_read
      module procedure read_real_1d, read_real_2d, read_int_1d, read_int_2d
   end interface h5io_read

contains

   !> Opens the existing file `path` read-only; a file its writer left
   !> marked as open for writing (a run killed while it wrote, in SWMR mode:
   !> src/results/results_hdf5.f90) is opened as a SWMR reader, which such a file
   !> admits.
   subroutine h5io_open_read(path, fid, stat, errmsg)
      !> File path.
      character(len=*), intent(in) :: path
      !> Id of the open file.
      integer(hid_t), intent(out) :: fid
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer :: err
      !> H5F_ACC_SWMR_READ (<H5Fpublic.h>, 0x0040), not in the HDF5 1.10 Fortran module
      integer, parameter :: acc_swmr_read = 64
      call h5fopen_f(path, H5F_ACC_RDONLY_F, fid, err)
      if (err /= 0) call h5fopen_f(path, ior(H5F_ACC_RDONLY_F, acc_swmr_read), fid, err)
      call h5io_check(err, 'cannot open the HDF5 file', path, stat, errmsg)
   end subroutine h5io_open_read

   !> Reads the real scalar attribute `name` of object `obj`.
   subroutine get_attr_real(loc, obj, name, x, stat, errmsg)
      !> File or group the object path starts from.
      integer(hid_t), intent(in) :: loc
      !> Object path and attribute name.
      character(len=*), intent(in) :: obj, name
      !> Value read.
      real(dp), intent(out), target :: x
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      x = 0.0_dp
      call take_attr(loc, obj, name, H5T_NATIVE_DOUBLE, c_loc(x), stat, errmsg)
   end subroutine get_attr_real

   !> Reads the integer scalar attribute `name` of object `obj`.
   subroutine get_attr_int(loc, obj, name, i, stat, errmsg)
      !> File or group the object path starts from.
      integer(hid_t), intent(in) :: loc
      !> Object path and attribute name.
      character(len=*), intent(in) :: obj, name
      !> Value read.
      integer, intent(out), target :: i
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      i = 0
      call take_attr(loc, obj, name, H5T_NATIVE_INTEGER, c_loc(i), stat, errmsg)
   end subroutine get_attr_int

   !> Reads the string attribute `name` of object `obj`, variable or fixed length.
   subroutine get_attr_string(loc, obj, name, s, stat, errmsg)
      !> File or group the object path starts from.
      integer(hid_t), intent(in) :: loc
      !> Object path and attribute name.
      character(len=*), intent(in) :: obj, name
      !> Value read, without the terminating null.
      character(len=:), allocatable, intent(out) :: s
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer(hid_t) :: aid, ftype, mtype, sid
      type(c_ptr), target :: ptr(1)
      type(c_ptr) :: to
      character(kind=c_char), allocatable, target :: fixed(:)
      character(kind=c_char), pointer :: chars(:)
      integer(size_t) :: nchar
      logical :: variable
      integer :: err, k, n

      s = ''
      call h5aopen_by_name_f(loc, obj, name, aid, err)
      call h5io_check(err, 'cannot open the attribute', h5io_attr_path(obj, name), stat, errmsg)
      if (stat /= 0) return
      call h5aget_type_f(aid, ftype, err)
      if (err == 0) call h5tis_variable_str_f(ftype, variable, err)
      if (err == 0) call h5tget_size_f(ftype, nchar, err)
      call h5io_check(err, 'cannot tell the type of the attribute', h5io_attr_path(obj, name), stat, errmsg)
      if (stat /= 0) then
         call h5aclose_f(aid, err)
         return
      end if
      if (variable) then
         call h5io_vlen_string_type(mtype, err)
         to = c_loc(ptr)
         if (err == 0) call h5aread_f(aid, mtype, to, err)
         call h5io_check(err, 'cannot read the attribute', h5io_attr_path(obj, name), stat, errmsg)
         if (stat == 0) then
            n = 0
            call c_f_pointer(ptr(1), chars, [huge(1)])
            do while (chars(n + 1) /= c_null_char)
               n = n + 1
            end do
            s = repeat(' ', n)
            do k = 1, n
               s(k:k) = chars(k)
            end do
            call h5aget_space_f(aid, sid, err)
            call h5dvlen_reclaim_f(mtype, sid, H5P_DEFAULT_F, to, err)
            call h5sclose_f(sid, err)
         end if
      else
         allocate (fixed(nchar + 1))
         fixed = c_null_char
         call h5tcopy_f(H5T_FORTRAN_S1, mtype, err)
         if (err == 0) call h5tset_size_f(mtype, nchar, err)
         to = c_loc(fixed)
         if (err == 0) call h5aread_f(aid, mtype, to, err)
         call h5io_check(err, 'cannot read the attribute', h5io_attr_path(obj, name), stat, errmsg)
         if (stat == 0) then
            n = 0
            do while (fixed(n + 1) /= c_null_char .and. n < int(nchar))
               n = n + 1
            end do
            s = repeat(' ', n)
            do k = 1, n
               s(k:k) = fixed(k)
            end do
            s = trim(s)
         end if
      end if
      call h5tclose_f(mtype, err)
      call h5tclose_f(ftype, err)
      call h5aclose_f(aid, err)
   end subroutine get_attr_string

   !> Reads a scalar attribute into buf, converted to the memory type tid.
   subroutine take_attr(loc, obj, name, tid, buf, stat, errmsg)
      !> File or group the object path starts from; memory type to read into.
      integer(hid_t), intent(in) :: loc, tid
      !> Object path and attribute name.
      character(len=*), intent(in) :: obj, name
      !> Address of the variable that receives the value.
      type(c_ptr), intent(in) :: buf
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer(hid_t) :: aid
      type(c_ptr) :: to
      integer :: err
      call h5aopen_by_name_f(loc, obj, name, aid, err)
      call h5io_check(err, 'cannot open the attribute', h5io_attr_path(obj, name), stat, errmsg)
      if (stat /= 0) return
      to = buf
      call h5aread_f(aid, tid, to, err)
      call h5io_check(err, 'cannot read the attribute', h5io_attr_path(obj, name), stat, errmsg)
      call h5aclose_f(aid, err)
   end subroutine take_attr

   !> Reads the rank-1 real dataset `name`.
   subroutine read_real_1d(loc, name, x, stat, errmsg)
      !> File or group the path starts from.
      integer(hid_t), intent(in) :: loc
      !> Dataset path.
      character(len=*), intent(in) :: name
      !> Values read.
      real(dp), allocatable, intent(out) :: x(:)
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer(hsize_t) :: dims(1)
      integer :: err
      call dataset_dims(loc, name, dims, stat, errmsg)
      if (stat /= 0) return
      allocate (x(dims(1)))
      if (size(x) == 0) return
      call h5ltread_dataset_double_f(loc, name, x, dims, err)
      call h5io_check(err, read_error, name, stat, errmsg)
   end subroutine read_real_1d

   !> Reads the rank-2 real dataset `name` (Fortran shape: C order reversed).
   subroutine read_real_2d(loc, name, x, stat, errmsg)
      !> File or group the path starts from.
      integer(hid_t), intent(in) :: loc
      !> Dataset path.
      character(len=*), intent(in) :: name
      !> Values read.
      real(dp), allocatable, intent(out) :: x(:,:)
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer(hsize_t) :: dims(2)
      integer :: err
      call dataset_dims(loc, name, dims, stat, errmsg)
      if (stat /= 0) return
      allocate (x(dims(1), dims(2)))
      if (size(x) == 0) return
      call h5ltread_dataset_double_f(loc, name, x, dims, err)
      call h5io_check(err, read_error, name, stat, errmsg)
   end subroutine read_real_2d

   !> Reads the rank-1 integer dataset `name`.
   subroutine read_int_1d(loc, name, i, stat, errmsg)
      !> File or group the path starts from.
      integer(hid_t), intent(in) :: loc
      !> Dataset path.
      character(len=*), intent(in) :: name
      !> Values read.
      integer, allocatable, intent(out) :: i(:)
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer(hsize_t) :: dims(1)
      integer :: err
      call dataset_dims(loc, name, dims, stat, errmsg)
      if (stat /= 0) return
      allocate (i(dims(1)))
      if (size(i) == 0) return
      call h5ltread_dataset_int_f(loc, name, i, dims, err)
      call h5io_check(err, read_error, name, stat, errmsg)
   end subroutine read_int_1d

   !> Reads the rank-2 integer dataset `name` (Fortran shape: C order reversed).
   subroutine read_int_2d(loc, name, i, stat, errmsg)
      !> File or group the path starts from.
      integer(hid_t), intent(in) :: loc
      !> Dataset path.
      character(len=*), intent(in) :: name
      !> Values read.
      integer, allocatable, intent(out) :: i(:,:)
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer(hsize_t) :: dims(2)
      integer :: err
      call dataset_dims(loc, name, dims, stat, errmsg)
      if (stat /= 0) return
      allocate (i(dims(1), dims(2)))
      if (size(i) == 0) return
      call h5ltread_dataset_int_f(loc, name, i, dims, err)
      call h5io_check(err, read_error, name, stat, errmsg)
   end subroutine read_int_2d

   !> The dimensions (Fortran order) of dataset `name`, which must have rank size(dims).
   subroutine dataset_dims(loc, name, dims, stat, errmsg)
      !> File or group the path starts from.
      integer(hid_t), intent(in) :: loc
      !> Dataset path.
      character(len=*), intent(in) :: name
      !> Its dimensions, Fortran order; their number is the rank expected.
      integer(hsize_t), intent(out) :: dims(:)
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      integer :: rank, type_class, err
      integer(size_t) :: type_size
      character(len=16) :: text
      dims = 0
      call h5ltget_dataset_ndims_f(loc, name, rank, err)
      call h5io_check(err, 'cannot find the dataset', name, stat, errmsg)
      if (stat /= 0) return
      if (rank /= size(dims)) then
         write (text, '(a,i0,a,i0)') ' ', rank, ', not ', size(dims)
         call h5io_fail('the dataset has rank'//trim(text), name, stat, errmsg)
         return
      end if
      call h5ltget_dataset_info_f(loc, name, dims, type_class, type_size, err)
      call h5io_check(err, 'cannot read the shape of the dataset', name, stat, errmsg)
   end subroutine dataset_dims

end module hdf5_read
