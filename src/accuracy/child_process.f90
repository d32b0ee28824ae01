!> Child processes of an accuracy run (src/accuracy/accuracy_driver.f90):
!> the program runs itself, through the C library (src/system/c_library.f90),
!> never through a shell.
!>
!>  - spawn_program: posix_spawn(3) of a program with an argument vector,
!>    its standard output and error into a log file; the arguments are
!>    passed as they are, one each, so nothing in them (a deck's path, a
!>    prefix) is ever interpreted;
!>  - wait_child: waitpid(2) for any child, with its exit status (128 + N
!>    for a child the signal N ended, as a shell reports it);
!>  - program_path: the running program, /proc/self/exe (readlink(2)),
!>    else the command's argument 0;
!>  - usable_cpus: the CPUs the process may run on, sched_getaffinity(2),
!>    or Slurm's SLURM_CPUS_PER_TASK / SLURM_CPUS_ON_NODE when set and
!>    smaller.
module child_process
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_ptr, c_null_ptr, c_null_char, c_loc, c_size_t, c_long
   use c_library, only: spawn_actions_t, cpu_set_t, c_environ, c_posix_spawn, c_spawn_actions_init, &
      c_spawn_actions_destroy, c_spawn_actions_addopen, c_spawn_actions_adddup2, c_waitpid, c_readlink, &
      c_sched_getaffinity, o_write_no_follow
   use number_text, only: int_str
   implicit none
   private
   public :: spawn_program, wait_child, program_path, usable_cpus

   !> Permissions of a log file created here, before the umask: rw-rw-rw-.
   integer(c_int), parameter :: log_mode = int(o'666', c_int)
   !> Standard output and standard error.
   integer(c_int), parameter :: fd_out = 1, fd_err = 2
   !> Longest path readlink is asked for.
   integer, parameter :: max_path = 4096

contains

   !> Starts the program `path` with the arguments `args` (argv[0] = path),
   !> its standard output and standard error written to `log_path`
   !> (created, or emptied), standard input and the environment inherited.
   subroutine spawn_program(path, args, log_path, pid, stat, errmsg)
      character(len=*), intent(in) :: path          !< the program
      character(len=*), intent(in) :: args(:)       !< its arguments, trailing blanks not part of them
      character(len=*), intent(in) :: log_path      !< where its output goes
      integer, intent(out) :: pid                   !< the child's process id
      integer, intent(out) :: stat                  !< 0, or the C library's error number
      character(len=*), intent(inout) :: errmsg     !< what failed
      type(spawn_actions_t) :: actions
      character(kind=c_char), allocatable, target :: chars(:)
      type(c_ptr), allocatable :: argv(:)
      integer(c_int) :: cpid, r
      integer :: i, at, ignored

      call pack_strings()
      pid = -1
      r = c_spawn_actions_init(actions)
      if (r == 0) r = c_spawn_actions_addopen(actions, fd_out, c_text(log_path), o_write_no_follow, &
                                             log_mode)
      if (r == 0) r = c_spawn_actions_adddup2(actions, fd_out, fd_err)
      if (r == 0) r = c_posix_spawn(cpid, c_text(path), actions, c_null_ptr, argv, c_environ)
      ignored = c_spawn_actions_destroy(actions)
      stat = r
      if (r /= 0) then
         errmsg = 'cannot start ' // path // ' (posix_spawn: error ' // int_str(r) // ')'
         return
      end if
      pid = cpid

   contains

      !> path and args as C strings in chars, and argv: the pointers to
      !> them, then a null pointer.
      subroutine pack_strings()
         allocate (chars(len_trim(path) + sum(len_trim(args)) + size(args) + 1), argv(size(args) + 2))
         at = 1
         call put(path, 1)
         do i = 1, size(args)
            call put(args(i), i + 1)
         end do
         argv(size(args) + 2) = c_null_ptr
      end subroutine pack_strings

      !> One string into the buffer, its pointer the n-th of argv.
      subroutine put(text, n)
         character(len=*), intent(in) :: text      !< the string (trailing blanks dropped)
         integer, intent(in) :: n                  !< its place in argv
         chars(at:at + len_trim(text) - 1) = transfer(trim(text), chars)
         chars(at + len_trim(text)) = c_null_char
         argv(n) = c_loc(chars(at))
         at = at + len_trim(text) + 1
      end subroutine put

   end subroutine spawn_program

   !> Waits for any child of the process to end.
   subroutine wait_child(pid, exit_code)
      integer, intent(out) :: pid          !< the child that ended, -1 when there is none
      integer, intent(out) :: exit_code    !< its exit status, 128 + N when the signal N ended it
      integer(c_int) :: status, r
      r = c_waitpid(-1_c_int, status, 0_c_int)
      pid = r
      exit_code = -1
      if (r <= 0) then
         pid = -1
         return
      end if
      if (iand(status, 127) == 0) then
         exit_code = iand(ishft(status, -8), 255)
      else
         exit_code = 128 + iand(status, 127)
      end if
   end subroutine wait_child

   !> The path of the running program: /proc/self/exe, or the command's
   !> argument 0 when that cannot be read.
   function program_path() result(path)
      character(len=:), allocatable :: path
      character(kind=c_char) :: buf(max_path)
      integer(c_long) :: n
      integer :: length
      n = c_readlink(c_text('/proc/self/exe'), buf, int(max_path, c_size_t))
      if (n > 0 .and. n < max_path) then
         allocate (character(len=n) :: path)
         path = transfer(buf(:n), path)
         return
      end if
      call get_command_argument(0, length=length)
      allocate (character(len=length) :: path)
      if (length > 0) call get_command_argument(0, path)
   end function program_path

   !> The CPUs the process may run on (at least 1): the affinity mask's,
   !> or Slurm's count for the task when it is set and smaller.
   integer function usable_cpus() result(n)
      type(cpu_set_t) :: mask
      integer :: i, slurm
      character(len=*), parameter :: slurm_vars(2) = [character(len=19) :: 'SLURM_CPUS_PER_TASK', 'SLURM_CPUS_ON_NODE']
      n = 1
      if (c_sched_getaffinity(0_c_int, int(storage_size(mask)/8, c_size_t), mask) == 0) &
         n = max(1, sum([(popcnt(mask%bits(i)), i = 1, size(mask%bits))]))
      do i = 1, size(slurm_vars)
         slurm = environment_count(trim(slurm_vars(i)))
         if (slurm > 0) n = min(n, slurm)
      end do
   end function usable_cpus

   !> A positive count from the environment variable `name`, 0 when it is
   !> not set or not a positive integer.
   integer function environment_count(name) result(count)
      character(len=*), intent(in) :: name    !< the variable
      character(len=32) :: text
      integer :: length, st, ios
      count = 0
      call get_environment_variable(name, text, length, st)
      if (st /= 0 .or. length == 0) return
      read (text, *, iostat=ios) count
      if (ios /= 0 .or. count < 0) count = 0
   end function environment_count

   !> text as a C string (null-terminated).
   pure function c_text(text) result(c)
      character(len=*), intent(in) :: text    !< the text
      character(kind=c_char, len=len(text) + 1) :: c
      c = text // c_null_char
   end function c_text

end module child_process
