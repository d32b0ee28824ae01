!> The other analyses of the same model, chosen by &analysis kind: the
!> static load (src/static_analysis.f90), the natural modes
!> (src/modal_analysis.f90) and the transient pressure
!> (src/pressure_analysis.f90). Each checks a part of the model on its own
!> (docs/VALIDATION.md) and writes its own result files.
module other_analyses
   use deck_schema, only: deck_t
   use plate_model, only: model_t
   use static_analysis, only: run_static
   use modal_analysis, only: run_modes
   use pressure_analysis, only: run_pressure
   implicit none
   private
   public :: run_other_analysis

contains

   !> Runs the analysis of deck%analysis_kind on the model; its report (a
   !> few lines) goes to unit.
   subroutine run_other_analysis(deck, model, unit, stat, errmsg)
      type(deck_t), intent(in) :: deck              !< the deck
      type(model_t), intent(in) :: model            !< the model
      integer, intent(in) :: unit                   !< where the report goes
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      character(len=2048) :: report
      report = ''
      stat = 0
      select case (deck%analysis_kind)
      case ('static');   call run_static(deck, model, report, stat, errmsg)
      case ('modes');    call run_modes(deck, model, report, stat, errmsg)
      case ('pressure'); call run_pressure(deck, model, report, stat, errmsg)
      end select
      if (len_trim(report) > 0) write (unit, '(a)') trim(report)
   end subroutine run_other_analysis

end module other_analyses
