!> The result files of every analysis: the claim before any work, the column files (title, deck
!> echo, a line per column, the names, the rows), the history's columns (for <prefix>_history.dat
!> and /history of <prefix>.h5) and the summary's items ('key = value', the unit in the key; also
!> /summary). Not from the paper. More: docs/OUTPUT.md.
module result_files
   use, intrinsic :: iso_fortran_env, only: int64
   use kinds, only: dp, msg_len
   use deck_schema, only: deck_t
   use deck_echo, only: echo_deck
   use file_system, only: make_directories, parent_directory, prefix_problem, name_problem, short_path, &
      path_kind, path_missing, path_regular, path_link, path_directory, path_other, create_new_file, remove_file, &
      file_lock_t, lock_file, unlock_file, rename_file, file_size, file_probe_t, probe_size
   use system_limits, only: name_max, path_max, read_only_file_system
   use number_text, only: put_f16_4, put_es16_7e3, put_i6, int_str
   implicit none
   private
   public :: column_t, history_columns, nhist, nhist_damage, history_width
   public :: col_time, col_force, col_alpha, col_w_plate, col_w_impactor, col_v_impactor, col_strain_y, &
             col_ke_impactor, col_ke_plate, col_strain_energy, col_contact_work, col_contact_energy, &
             col_energy_error, col_branch, col_contact_iter, col_solves, col_failure_index, col_failure_mode, &
             col_damage_dissipated
   public :: summary_item_t, summary_real, summary_integer, summary_text
   public :: results_claim_t, result_suffixes, claim_results, release_results, claim_left_empty
   public :: keep_failure, open_columns, open_history, write_column_block, write_history_row, reserve_summary, &
             write_summary_file

   !> One column of the history.
   type :: column_t
      character(len=20) :: name        !< its name in <prefix>.h5 (/history/<name>), SI
      character(len=24) :: file_name   !< its name in <prefix>_history.dat, with the file's unit
      character(len=4) :: unit         !< SI unit in the .h5
      character(len=4) :: file_unit    !< unit in the file
      real(dp) :: scale                !< value in the file = SI value * scale
      character(len=72) :: meaning     !< what it is
      logical :: whole = .false.       !< an integer (written as one)
      logical :: strength = .false.    !< only with &strength (ply stresses), after the others
   end type column_t

   !> The history's columns, in the order of the file: the first nhist in
   !> every run, then &strength's, then ply damage's (history_width).
   integer, parameter :: col_time = 1, col_force = 2, col_alpha = 3, col_w_plate = 4, col_w_impactor = 5, &
      col_v_impactor = 6, col_strain_y = 7, col_ke_impactor = 8, col_ke_plate = 9, col_strain_energy = 10, &
      col_contact_work = 11, col_contact_energy = 12, col_energy_error = 13, col_branch = 14, &
      col_contact_iter = 15, col_solves = 16, nhist = 16, col_failure_index = 17, col_failure_mode = 18, &
      nhist_strength = 18, col_damage_dissipated = 19, nhist_damage = 19
   type(column_t), parameter :: history_columns(nhist_damage) = [ &
      column_t('time', 'time_us', 's', 'us', 1.0e6_dp, 'time'), &
      column_t('force', 'force_N', 'N', 'N', 1.0_dp, 'contact force on the whole plate F'), &
      column_t('indentation', 'indentation_mm', 'm', 'mm', 1.0e3_dp, &
         'indentation alpha = w_impactor - w_plate, eq. (13)'), &
      column_t('w_plate', 'w_plate_mm', 'm', 'mm', 1.0e3_dp, &
         'plate deflection under the impactor (pressure-weighted mean)'), &
      column_t('w_impactor', 'w_impactor_mm', 'm', 'mm', 1.0e3_dp, 'impactor displacement since first touch'), &
      column_t('v_impactor', 'v_impactor_m_s', 'm/s', 'm/s', 1.0_dp, &
         'impactor velocity, positive towards the plate'), &
      column_t('strain_y_back', 'strain_y_back', '-', '-', 1.0_dp, &
         'in-plane y strain on the back face at the gauge (Fig. 9b, 10b)'), &
      column_t('ke_impactor', 'ke_impactor_J', 'J', 'J', 1.0_dp, 'impactor kinetic energy'), &
      column_t('ke_plate', 'ke_plate_J', 'J', 'J', 1.0_dp, 'plate kinetic energy, whole plate'), &
      column_t('strain_energy', 'strain_energy_J', 'J', 'J', 1.0_dp, 'plate strain energy, whole plate'), &
      column_t('contact_work', 'contact_work_J', 'J', 'J', 1.0_dp, &
         'work of the contact force on the plate, int F p^T dD'), &
      column_t('indentation_energy', 'indentation_energy_J', 'J', 'J', 1.0_dp, &
         'energy the contact took: the impactor''s work less contact_work'), &
      column_t('energy_error', 'energy_error_J', 'J', 'J', 1.0_dp, &
         'E0 - (ke_impactor + ke_plate + strain_energy + indentation_energy)'), &
      column_t('branch', 'branch', '-', '-', 1.0_dp, &
         'contact law branch: 0 none, 1 loading, 2 unloading, 3 reloading', whole=.true.), &
      column_t('contact_iter', 'contact_iter', '-', '-', 1.0_dp, &
         'contact-force iterations of the step, eq. (17)', whole=.true.), &
      column_t('nonlinear_iter', 'nonlinear_iter', '-', '-', 1.0_dp, 'plate solutions of the step, eq. (19)', whole=.true.), &
      column_t('failure_index', 'failure_index', '-', '-', 1.0_dp, &
         'largest ply failure index of the step (&strength criterion)', strength=.true.), &
      column_t('failure_mode', 'failure_mode', '-', '-', 1.0_dp, &
         'its mode: 1/2 fibre t/c, 3/4 matrix t/c, 5 shear 12-13, 6 shear 23', whole=.true., strength=.true.), &
      column_t('damage_dissipated', 'damage_dissipated_J', 'J', 'J', 1.0_dp, &
         'energy dissipated by ply damage, whole plate (&damage)', strength=.true.) ]

   !> A run's hold on its result files (claim_results).
   type :: results_claim_t
      type(file_lock_t) :: lock                    !< the lock on the first file
      character(len=:), allocatable :: first       !< the first file's path
      logical :: created = .false.                 !< the claim created it (empty)
   end type results_claim_t

   !> A file replaced in one step is written under <file>.tmp, then renamed.
   character(len=*), parameter :: temporary = '.tmp'

   !> Bytes reserved for the summary before a run (reserve_summary).
   integer, parameter :: summary_reserve = 65536

   !> Bytes of a history row on disk (twice that with ply damage): a power of
   !> two, the header padded to a multiple of it, so that no row straddles
   !> a 4 KiB page and a killed run's rows are all whole.
   integer, parameter :: history_slot = 256

   !> Kinds of summary item.
   integer, parameter :: item_real = 1, item_integer = 2, item_text = 3

   !> One line of the summary.
   type :: summary_item_t
      character(len=:), allocatable :: key      !< in <prefix>_summary.dat, with the file's unit
      character(len=:), allocatable :: name     !< in /summary of <prefix>.h5, SI
      character(len=:), allocatable :: unit     !< SI unit ('-' none)
      character(len=:), allocatable :: text     !< the value as the file writes it
      real(dp) :: si = 0.0_dp                   !< the value in SI (real and integer items)
      integer :: kind = item_real               !< item_real, item_integer or item_text
   end type summary_item_t

contains

   !> The result files of an analysis after the prefix; a run claims and locks the first.
   pure function result_suffixes(analysis_kind) result(list)
      character(len=*), intent(in) :: analysis_kind   !< 'impact', 'static', 'modes' or 'pressure'
      character(len=24), allocatable :: list(:)
      select case (analysis_kind)
      case ('static');   list = [character(len=24) :: '_static.dat', '_deflection.dat']
      case ('modes');    list = [character(len=24) :: '_modes.dat', '_mode_shapes.dat']
      case ('pressure'); list = [character(len=24) :: '_pressure_history.dat']
      case default;      list = [character(len=24) :: '_history.dat', '_summary.dat', '.h5', '.xdmf']
      end select
   end function result_suffixes

   !> Before any work a run claims its files (result_suffixes): their names
   !> fit (NAME_MAX, PATH_MAX), the prefix's directories are made, no file
   !> exists unless &output overwrite, none (nor <file>.tmp) is a link or not a
   !> regular file; the first is created exclusively and locked until the end.
   subroutine claim_results(deck, suffixes, claim, stat, errmsg)
      type(deck_t), intent(in) :: deck              !< effective deck (prefix, overwrite)
      character(len=*), intent(in) :: suffixes(:)   !< the run's file names after the prefix
      type(results_claim_t), intent(out) :: claim   !< the claim, held until release_results
      integer, intent(out) :: stat                  !< 0 when the run may write its results
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      character(len=:), allocatable :: head, why
      character(len=msg_len) :: iomsg
      head = deck%source // ": &output: prefix = '" // short_path(deck%prefix) // "': "
      stat = 1
      why = prefix_problem(deck%prefix)
      if (len(why) == 0) why = names_problem(deck%prefix, suffixes)
      if (len(why) > 0) then
         errmsg = head // why
         return
      end if
      call make_directories(parent_directory(deck%prefix), stat, iomsg)
      if (stat /= 0) then
         errmsg = head // trim(iomsg) // read_only_note(deck%prefix)
         return
      end if
      why = files_problem(deck%prefix, suffixes, deck%overwrite)
      if (len(why) > 0) then
         stat = 1
         errmsg = head // why
         return
      end if
      claim%first = deck%prefix // trim(suffixes(1))
      if (path_kind(claim%first) == path_missing) then
         ! created exclusively (O_CREAT | O_EXCL): of two runs, one does
         call create_new_file(claim%first, stat, iomsg)
         if (stat /= 0) then
            errmsg = head // 'cannot write ' // short_path(claim%first) // ': ' // trim(iomsg) &
               // read_only_note(deck%prefix)
            if (path_kind(claim%first) /= path_missing) errmsg = head // short_path(claim%first) &
               // ' was just created by another run with the same prefix: choose another prefix'
            return
         end if
         claim%created = .true.
      end if
      call lock_file(claim%first, claim%lock, stat, iomsg)
      if (stat /= 0) errmsg = head // trim(iomsg) // ': choose another prefix, or wait for that run to end'
   end subroutine claim_results

   !> A run killed in its set-up left its claim and nothing else: the first
   !> file exists, empty, and no other result file does.
   logical function claim_left_empty(prefix, suffixes) result(left)
      character(len=*), intent(in) :: prefix        !< the prefix
      character(len=*), intent(in) :: suffixes(:)   !< the run's file names after it
      integer :: i
      left = path_kind(prefix // trim(suffixes(1))) == path_regular
      if (left) left = file_size(prefix // trim(suffixes(1))) == 0
      do i = 2, size(suffixes)
         if (left) left = path_kind(prefix // trim(suffixes(i))) == path_missing
      end do
   end function claim_left_empty

   !> Why the run's file names cannot be made where the prefix is ('' when
   !> they can): a name (with .tmp) beyond NAME_MAX, a path beyond PATH_MAX.
   function names_problem(prefix, suffixes) result(why)
      character(len=*), intent(in) :: prefix        !< the prefix
      character(len=*), intent(in) :: suffixes(:)   !< the file names after it
      character(len=:), allocatable :: why
      integer :: i, longest
      longest = 1
      do i = 2, size(suffixes)
         if (len_trim(suffixes(i)) > len_trim(suffixes(longest))) longest = i
      end do
      why = name_problem(prefix // trim(suffixes(longest)) // temporary, name_max(prefix), path_max)
   end function names_problem

   !> Why the run cannot write its files ('' when it can): a link, not a regular
   !> file, or a file that exists without overwrite.
   function files_problem(prefix, suffixes, overwrite) result(why)
      character(len=*), intent(in) :: prefix        !< the prefix
      character(len=*), intent(in) :: suffixes(:)   !< the file names after it
      logical, intent(in) :: overwrite              !< &output overwrite (or --overwrite)
      character(len=:), allocatable :: why
      character(len=:), allocatable :: path
      integer :: i, k
      why = ''
      files: do i = 1, size(suffixes)
         do k = 1, 2
            path = prefix // trim(suffixes(i))
            if (k == 2) path = path // temporary
            select case (path_kind(path))
            case (path_link)
               why = short_path(path) // ' is a symbolic link: a run writes no file through a link (it would ' &
                  // 'change the file it points to): remove the link, or choose another prefix'
            case (path_directory, path_other)
               why = short_path(path) // ' exists and is not a regular file: choose another prefix'
            case (path_regular)
               if (k == 1 .and. .not. overwrite) why = short_path(path) // ' exists, the results of another ' &
                  // 'run: choose another prefix, or set overwrite = .true. in &output (or run impact ' &
                  // '--overwrite) to replace them'
            end select
            if (len(why) > 0) return
         end do
      end do files
   end function files_problem

   !> ' (the file system is read-only)' when the prefix is on one, '' else.
   function read_only_note(prefix) result(note)
      character(len=*), intent(in) :: prefix        !< the prefix
      character(len=:), allocatable :: note
      note = ''
      if (read_only_file_system(prefix)) note = ' (the file system is read-only)'
   end function read_only_note

   !> Ends a claim: the lock released; with `discard`, the first file removed
   !> when the claim created it and it is still empty.
   subroutine release_results(claim, discard)
      type(results_claim_t), intent(inout) :: claim  !< the claim
      logical, intent(in) :: discard                 !< remove the first file if still as created
      integer :: ios
      if (discard .and. claim%created) then
         if (path_kind(claim%first) == path_regular) then
            if (file_size(claim%first) == 0) call remove_file(claim%first, ios)
         end if
      end if
      call unlock_file(claim%lock)
      claim%created = .false.
   end subroutine release_results

   !> The first failure kept: stat and errmsg take ios and text when stat is 0.
   pure subroutine keep_failure(stat, errmsg, ios, text)
      integer, intent(inout) :: stat              !< 0, or the first failure
      character(len=*), intent(inout) :: errmsg   !< its reason
      integer, intent(in) :: ios                  !< the status of the call just made
      character(len=*), intent(in) :: text        !< its reason
      if (ios == 0 .or. stat /= 0) return
      stat = ios
      errmsg = text
   end subroutine keep_failure

   !> Opens <prefix><suffix> (claimed before) and writes its header (write_header).
   subroutine open_columns(deck, suffix, title, names, texts, unit, stat, errmsg)
      type(deck_t), intent(in) :: deck            !< effective deck (echoed; prefix)
      character(len=*), intent(in) :: suffix      !< file name after the prefix, e.g. '_static.dat'
      character(len=*), intent(in) :: title       !< first line, after '# '
      character(len=*), intent(in) :: names(:)    !< column names (with their unit)
      character(len=*), intent(in) :: texts(:)    !< column meanings (with their unit)
      integer, intent(out) :: unit                !< the open file, <prefix><suffix>
      integer, intent(out) :: stat                !< 0 on success
      character(len=*), intent(inout) :: errmsg   !< reason on failure
      character(len=msg_len) :: iomsg
      character(len=:), allocatable :: path
      path = deck%prefix // suffix
      if (path_kind(path) == path_link) then
         stat = 1
         errmsg = deck%source // ": &output: prefix = '" // short_path(deck%prefix) // "': " // short_path(path) &
            // ' is a symbolic link: a run writes no file through a link'
         return
      end if
      open (newunit=unit, file=path, status='replace', action='write', iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         errmsg = deck%source // ": &output: prefix = '" // short_path(deck%prefix) // "': cannot write " &
            // short_path(path) // ': ' // trim(iomsg)
         return
      end if
      call write_header(unit, deck, title, names, texts, 0)
   end subroutine open_columns

   !> The history file, opened as open_columns does, its header padded with
   !> blanks after the names line to end at a multiple of its row's slot.
   subroutine open_history(deck, title, names, texts, unit, path, stat, errmsg)
      type(deck_t), intent(in) :: deck            !< effective deck (echoed; prefix)
      character(len=*), intent(in) :: title       !< first line, after '# '
      character(len=*), intent(in) :: names(:)    !< column names (with their unit)
      character(len=*), intent(in) :: texts(:)    !< column meanings (with their unit)
      integer, intent(out) :: unit                !< the open file
      character(len=:), allocatable, intent(out) :: path   !< its path
      integer, intent(out) :: stat                !< 0 on success
      character(len=*), intent(inout) :: errmsg   !< reason on failure
      integer :: pad
      path = deck%prefix // '_history.dat'
      call open_columns(deck, '_history.dat', title, names, texts, unit, stat, errmsg)
      if (stat /= 0) return
      pad = int(modulo(-file_size(path), int(merge(2, 1, size(names) > nhist_strength)*history_slot, int64)))
      if (pad == 0) return
      rewind (unit)
      call write_header(unit, deck, title, names, texts, pad)
   end subroutine open_history

   !> A column file's header: title, deck echo, column block (`blanks` after the names).
   subroutine write_header(unit, deck, title, names, texts, blanks)
      integer, intent(in) :: unit                 !< the open file
      type(deck_t), intent(in) :: deck            !< effective deck (echoed)
      character(len=*), intent(in) :: title       !< first line, after '# '
      character(len=*), intent(in) :: names(:)    !< column names (with their unit)
      character(len=*), intent(in) :: texts(:)    !< column meanings (with their unit)
      integer, intent(in) :: blanks               !< after the names line
      write (unit, '(a)') '# ' // title
      call echo_deck(deck, unit, '# ')
      call write_column_block(unit, names, texts, blanks)
      flush (unit)
   end subroutine write_header

   !> The column block of a header: '# columns:', a line per column, then the
   !> names on one '#' line (and `blanks` blanks).
   subroutine write_column_block(unit, names, texts, blanks)
      integer, intent(in) :: unit                 !< open formatted unit
      character(len=*), intent(in) :: names(:)    !< column names (with their unit)
      character(len=*), intent(in) :: texts(:)    !< column meanings (with their unit)
      integer, intent(in), optional :: blanks     !< blanks at the end of the names line
      integer :: c
      write (unit, '(a)') '# columns:'
      do c = 1, size(names)
         write (unit, '(a,i2,1x,a,1x,a)') '# ', c, names(c), trim(texts(c))
      end do
      write (unit, '(a)', advance='no') '#'
      do c = 1, size(names)
         write (unit, '(1x,a)', advance='no') trim(names(c))
      end do
      if (present(blanks)) write (unit, '(a)', advance='no') repeat(' ', blanks)
      write (unit, '(a)') ''
   end subroutine write_column_block

   !> The history's columns of a run: nhist, nhist_strength when the deck
   !> gives &strength, nhist_damage with ply damage.
   pure integer function history_width(with_strength, with_damage)
      logical, intent(in) :: with_strength, with_damage   !< ply stresses computed; plies damaged (&damage)
      history_width = merge(nhist_damage, merge(nhist_strength, nhist, with_strength), with_damage)
   end function history_width

   !> One history row, SI values in history_columns' order, written in the
   !> file's units, flushed, and checked on disk (the file grew by the row).
   subroutine write_history_row(unit, probe, values, bytes, stat, iomsg)
      integer, intent(in) :: unit                 !< the history file
      type(file_probe_t), intent(in) :: probe     !< the same file, open for its length on disk
      real(dp), intent(in) :: values(:)           !< the row, SI (history_width values)
      integer(int64), intent(inout) :: bytes      !< the file's length on disk before the row, then after it
      integer, intent(out) :: stat                !< 0, or the write's iostat
      character(len=*), intent(inout) :: iomsg    !< the run-time's message on failure
      character(len=2*history_slot - 1) :: line
      integer(int64) :: after
      integer :: c, at, slot
      line = ''
      ! the text of the format (f16.4, 12es16.7e3, 3i6), then es16.7e3 or i6 for
      ! each further column, byte for byte, by src/system/number_text.f90's writers
      call put_f16_4(values(1)*history_columns(1)%scale, line(1:16))
      at = 16
      columns: do c = 2, size(values)
         if (history_columns(c)%whole) then
            call put_i6(nint(values(c)), line(at + 1:at + 6))
            at = at + 6
         else
            call put_es16_7e3(values(c)*history_columns(c)%scale, line(at + 1:at + 16))
            at = at + 16
         end if
      end do columns
      slot = merge(2, 1, size(values) > nhist_strength)*history_slot
      write (unit, '(a)', iostat=stat, iomsg=iomsg) line(:slot - 1)     ! the whole slot
      if (stat == 0) flush (unit, iostat=stat, iomsg=iomsg)
      if (stat /= 0) return
      ! gfortran 12's FLUSH does not report a failed write(2): the length on disk does
      after = probe_size(probe)
      if (after /= bytes + slot) then
         stat = 1
         iomsg = 'the row did not reach the disk (a full disk, or the file-size limit)'
         return
      end if
      bytes = after
   end subroutine write_history_row

   !> Appends a real item: the file's key, the SI name, unit and value, the
   !> file's scale; with `given` false, the text item `none` instead.
   subroutine summary_real(items, key, name, unit, si, scale, given, none)
      type(summary_item_t), allocatable, intent(inout) :: items(:)
      character(len=*), intent(in) :: key, name, unit
      real(dp), intent(in) :: si, scale
      logical, intent(in), optional :: given
      character(len=*), intent(in), optional :: none
      character(len=24) :: buf
      if (present(given)) then
         if (.not. given) call summary_text(items, key, none)
         if (.not. given) return
      end if
      write (buf, '(es15.7)') si*scale
      call append(items, key, name, unit, trim(adjustl(buf)), si, item_real)
   end subroutine summary_real

   !> Appends an integer item (no unit).
   subroutine summary_integer(items, key, value)
      type(summary_item_t), allocatable, intent(inout) :: items(:)
      character(len=*), intent(in) :: key
      integer, intent(in) :: value
      call append(items, key, key, '-', int_str(value), real(value, dp), item_integer)
   end subroutine summary_integer

   !> Appends a text item ('completed', 'none', 'true').
   subroutine summary_text(items, key, value)
      type(summary_item_t), allocatable, intent(inout) :: items(:)
      character(len=*), intent(in) :: key, value
      call append(items, key, key, '-', value, 0.0_dp, item_text)
   end subroutine summary_text

   !> Appends an item, component by component (gfortran 12's constructor loses them).
   subroutine append(items, key, name, unit, text, si, kind)
      type(summary_item_t), allocatable, intent(inout) :: items(:)
      character(len=*), intent(in) :: key, name, unit, text
      real(dp), intent(in) :: si
      integer, intent(in) :: kind
      type(summary_item_t), allocatable :: grown(:)
      integer :: n
      n = 0
      if (allocated(items)) n = size(items)
      allocate (grown(n + 1))
      if (n > 0) grown(:n) = items
      grown(n + 1)%key = key
      grown(n + 1)%name = name
      grown(n + 1)%unit = unit
      grown(n + 1)%text = text
      grown(n + 1)%si = si
      grown(n + 1)%kind = kind
      call move_alloc(grown, items)
   end subroutine append

   !> Reserves <prefix>_summary.dat.tmp (summary_reserve bytes), which
   !> write_summary_file writes over: a run stopped by a full disk still reports.
   subroutine reserve_summary(deck, stat, errmsg)
      type(deck_t), intent(in) :: deck                  !< effective deck (prefix)
      integer, intent(out) :: stat                      !< 0 on success
      character(len=*), intent(inout) :: errmsg        !< reason on failure, naming the file
      integer, parameter :: line_len = 63, lines = summary_reserve/(line_len + 1)
      character(len=msg_len) :: iomsg
      character(len=:), allocatable :: path
      integer :: u, i
      path = deck%prefix // '_summary.dat' // temporary
      call remove_file(path, i)        ! one a killed run left (a link itself, never what it points to)
      open (newunit=u, file=path, status='new', action='write', iostat=stat, iomsg=iomsg)
      if (stat /= 0) then              ! (u is undefined: no close, which could close standard error)
         errmsg = short_path(path) // ': ' // trim(iomsg)
         return
      end if
      do i = 1, lines
         write (u, '(a)', iostat=stat, iomsg=iomsg) '#' // repeat(' ', line_len - 1)
         if (stat /= 0) exit
      end do
      if (stat == 0) then
         close (u, iostat=stat, iomsg=iomsg)
      else
         close (u, status='delete', iostat=i)
      end if
      if (stat /= 0) errmsg = short_path(path) // ': ' // trim(iomsg)
   end subroutine reserve_summary

   !> Writes <prefix>_summary.dat (title, deck echo, 'key = value' lines) whole
   !> to <prefix>_summary.dat.tmp and renames it: the previous file or complete.
   subroutine write_summary_file(deck, items, stat, errmsg)
      type(deck_t), intent(in) :: deck                  !< effective deck
      type(summary_item_t), intent(in) :: items(:)      !< the summary
      integer, intent(out) :: stat                      !< 0 on success
      character(len=*), intent(inout) :: errmsg        !< reason on failure, naming the file
      character(len=msg_len) :: iomsg
      character(len=:), allocatable :: path
      integer :: u, i
      path = deck%prefix // '_summary.dat'
      if (path_kind(path // temporary) == path_regular) then    ! written over the reserved space, then cut
         open (newunit=u, file=path // temporary, status='old', action='readwrite', position='rewind', &
               iostat=stat, iomsg=iomsg)
      else
         call remove_file(path // temporary, i)
         open (newunit=u, file=path // temporary, status='new', action='write', iostat=stat, iomsg=iomsg)
      end if
      if (stat /= 0) then              ! (u is undefined: no close, which could close standard error)
         errmsg = short_path(path) // ': ' // trim(iomsg)
         return
      end if
      write (u, '(a)', iostat=stat, iomsg=iomsg) &
         '# impact: summary (key = value; units in the key names)'
      if (stat == 0) call echo_deck(deck, u, '# ')
      do i = 1, size(items)
         if (stat /= 0) exit
         write (u, '(a)', iostat=stat, iomsg=iomsg) items(i)%key // ' = ' // items(i)%text
      end do
      if (stat == 0) endfile (u, iostat=stat, iomsg=iomsg)
      if (stat == 0) then
         close (u, iostat=stat, iomsg=iomsg)
      else
         close (u, iostat=i)
      end if
      if (stat == 0) call rename_file(path // temporary, path, stat, iomsg)
      if (stat /= 0) errmsg = short_path(path) // ': ' // trim(iomsg)
   end subroutine write_summary_file

end module result_files
