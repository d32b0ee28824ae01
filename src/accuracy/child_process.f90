!> Child processes through the C library, never a shell: spawn_program (posix_spawn(3), the output
!> into a log file never through a link, the child in a process group of its own); wait_child
!> (waitpid(2)); pass_stops_to_children (a stop signal recorded, stop_caught, and sent on to every
!> child's group); die_with_parent (PR_SET_PDEATHSIG with IMPACT_PARENT_PID); program_path;
!> usable_cpus (sched_getaffinity, or Slurm's count when smaller). The children and the signal
!> caught are module state, as in process_stop: a signal handler reaches nothing else.
module child_process
   use, intrinsic :: iso_c_binding, only: c_int, c_int16_t, c_char, c_ptr, c_null_ptr, c_null_char, c_loc, c_size_t, &
      c_long, c_funptr, c_funloc
   use c_library, only: spawn_actions_t, spawn_attr_t, cpu_set_t, c_posix_spawn, c_spawn_actions_init, &
      c_spawn_actions_destroy, c_spawn_actions_addopen, c_spawn_actions_adddup2, c_spawnattr_init, &
      c_spawnattr_destroy, c_spawnattr_setflags, c_spawnattr_setpgroup, c_waitpid, c_readlink, &
      c_sched_getaffinity, c_kill, c_getpid, c_getppid, c_prctl, c_signal, c_exit, o_write_no_follow
   use process_stop, only: stop_signals
   use number_text, only: int_str
   implicit none
   private
   public :: spawn_program, wait_child, program_path, usable_cpus, pass_stops_to_children, stop_caught, &
             die_with_parent

   !> The environment variable that makes a child die with its parent.
   character(len=*), parameter :: parent_variable = 'IMPACT_PARENT_PID'
   !> POSIX_SPAWN_SETPGROUP (glibc), PR_SET_PDEATHSIG, SIGKILL, ELOOP (open(2) with O_NOFOLLOW
   !> on a link), a log file's permissions before the umask, standard output and error.
   integer(c_int16_t), parameter :: spawn_setpgroup = 2_c_int16_t
   integer(c_int), parameter :: pr_set_pdeathsig = 1, sigkill = 9, eloop = 40, log_mode = int(o'666', c_int), &
      fd_out = 1, fd_err = 2
   !> The longest path read, the children held at most; their ids, and the signal caught (0: none).
   integer, parameter :: max_path = 4096, max_children = 256
   integer(c_int), volatile, save :: children(max_children) = 0, stopped = 0

contains

   !> Starts the program `path` with `args`, its output and errors into `log_path` (emptied), in a
   !> process group of its own, its environment IMPACT_PARENT_PID=<pid> and /proc/self/environ's.
   subroutine spawn_program(path, args, log_path, pid, stat, errmsg)
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: args(:)       !< its arguments, trailing blanks not part of them
      character(len=*), intent(in) :: log_path      !< where its output goes
      integer, intent(out) :: pid                   !< the child's process id
      integer, intent(out) :: stat                  !< 0, or the C library's error number
      character(len=*), intent(inout) :: errmsg
      type(spawn_actions_t) :: actions
      type(spawn_attr_t) :: attr
      character(kind=c_char), allocatable, target :: chars(:), env(:)
      character(len=:), allocatable :: text
      integer(c_int) :: cpid
      integer :: i, ignored, u, ios, n
      text = trim(path) // c_null_char                 ! the program and its arguments as C strings
      do i = 1, size(args)
         text = text // trim(args(i)) // c_null_char
      end do
      chars = transfer(text, c_null_char, len(text))
      text = parent_variable // '=' // int_str(int(c_getpid())) // c_null_char   ! and the environment
      n = len(text)
      allocate (env(n + 4096))
      env(:n) = transfer(text, env, n)
      open (newunit=u, file='/proc/self/environ', access='stream', form='unformatted', action='read', iostat=ios)
      do while (ios == 0)
         if (n == size(env)) env = [env, env]
         read (u, iostat=ios) env(n + 1)
         if (ios == 0) n = n + 1
      end do
      if (ios > 0 .or. env(n) /= c_null_char) n = len(text)   ! unreadable: ours alone
      close (u, iostat=ios)
      pid = -1
      stat = c_spawn_actions_init(actions)
      if (stat == 0) stat = c_spawnattr_init(attr)
      if (stat == 0) stat = c_spawnattr_setflags(attr, spawn_setpgroup)
      if (stat == 0) stat = c_spawnattr_setpgroup(attr, 0_c_int)          ! its own group, led by itself
      if (stat == 0) stat = c_spawn_actions_addopen(actions, fd_out, log_path // c_null_char, &
                                                    o_write_no_follow, log_mode)
      if (stat == 0) stat = c_spawn_actions_adddup2(actions, fd_out, fd_err)
      if (stat == 0) stat = c_posix_spawn(cpid, path // c_null_char, actions, attr, pointers(chars), &
                                          pointers(env(:n)))
      ignored = c_spawn_actions_destroy(actions)
      ignored = c_spawnattr_destroy(attr)
      if (stat /= 0) errmsg = 'cannot start ' // path // ' (posix_spawn: error ' // int_str(stat) // ')'
      if (stat == eloop) errmsg = log_path // ' is a symbolic link: a run writes no file through a link'
      if (stat /= 0) return
      pid = cpid
      i = findloc(children, 0_c_int, dim=1)
      if (i > 0) children(i) = cpid
      if (stopped /= 0) ignored = c_kill(-cpid, stopped)             ! a stop came while it started
   contains
      !> argv or envp: the C strings in s, one at 1 and after each nul but the last, then null.
      function pointers(s) result(p)
         character(kind=c_char), intent(in), target :: s(:)
         type(c_ptr), allocatable :: p(:)
         integer :: k
         p = [pack([(c_loc(s(k)), k = 1, size(s))], [.true., s(:size(s) - 1) == c_null_char]), c_null_ptr]
      end function pointers
   end subroutine spawn_program

   !> Waits for any child of the process to end.
   subroutine wait_child(pid, exit_code)
      integer, intent(out) :: pid, exit_code   !< the child ended (-1: none); its status (128 + N: signal N)
      integer(c_int) :: status, r
      r = c_waitpid(-1_c_int, status, 0_c_int)
      pid = merge(int(r), -1, r > 0)
      exit_code = -1
      if (r <= 0) return
      where (children == r) children = 0
      exit_code = merge(iand(ishft(status, -8), 255), 128 + iand(status, 127), iand(status, 127) == 0)
   end subroutine wait_child

   !> From now on a stop signal is recorded (stop_caught) and sent on to every child's group.
   subroutine pass_stops_to_children()
      type(c_funptr) :: previous
      integer :: k
      stopped = 0
      do k = 1, size(stop_signals)
         previous = c_signal(stop_signals(k), c_funloc(on_stop))
      end do
   end subroutine pass_stops_to_children

   !> The handler: records the signal and sends it on (kill(2), which POSIX allows in a handler).
   subroutine on_stop(signum) bind(c)
      integer(c_int), value :: signum   !< the signal received
      integer :: k
      integer(c_int) :: r
      stopped = signum
      do k = 1, max_children
         if (children(k) > 0) r = c_kill(-children(k), signum)
      end do
   end subroutine on_stop

   !> The stop signal caught since pass_stops_to_children, 0 if none.
   integer function stop_caught() result(signum)
      signum = int(stopped)
   end function stop_caught

   !> With IMPACT_PARENT_PID: SIGKILL when the parent ends, or at once when it has ended already.
   subroutine die_with_parent()
      character(len=24) :: text
      integer :: st, parent
      integer(c_int) :: r
      call get_environment_variable(parent_variable, text, status=st)
      if (st == 0) read (text, *, iostat=st) parent        ! none, or blank: st /= 0
      if (st /= 0) return
      r = c_prctl(pr_set_pdeathsig, int(sigkill, c_long))
      if (c_getppid() /= parent) call c_exit(128_c_int + sigkill)
   end subroutine die_with_parent

   !> The path of the running program: /proc/self/exe, else the command's argument 0.
   function program_path() result(path)
      character(len=:), allocatable :: path
      character(kind=c_char) :: buf(max_path)
      integer(c_long) :: n
      integer :: length
      call get_command_argument(0, length=length)
      allocate (character(len=length) :: path)
      call get_command_argument(0, path)
      n = c_readlink('/proc/self/exe' // c_null_char, buf, int(max_path, c_size_t))
      if (n > 0 .and. n < max_path) path = transfer(buf(:n), repeat(' ', int(n)))
   end function program_path

   !> The CPUs the process may run on (at least 1): the affinity mask's, or Slurm's when smaller.
   integer function usable_cpus() result(n)
      type(cpu_set_t) :: mask
      integer :: i, slurm, st
      character(len=32) :: text
      character(len=*), parameter :: slurm_vars(2) = [character(len=19) :: 'SLURM_CPUS_PER_TASK', 'SLURM_CPUS_ON_NODE']
      n = 1
      if (c_sched_getaffinity(0_c_int, int(storage_size(mask)/8, c_size_t), mask) == 0) &
         n = max(1, sum([(popcnt(mask%bits(i)), i = 1, size(mask%bits))]))
      do i = 1, size(slurm_vars)
         call get_environment_variable(trim(slurm_vars(i)), text, status=st)
         if (st == 0) read (text, *, iostat=st) slurm     ! none, or blank: st /= 0
         if (st == 0 .and. slurm > 0) n = min(n, slurm)
      end do
   end function usable_cpus

end module child_process
