!> The summary's extremes between the steps: the vertex of the parabola
!> through the largest sample and its neighbours (O(dt^3) at a smooth
!> maximum, the largest sample O(dt^2)), and where a line through two samples
!> crosses 0 (a contact's end). Not from the paper. More: docs/OUTPUT.md.
module step_peak
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite
   use kinds, only: dp
   implicit none
   private
   public :: peak_track_t, peak_sample, peak_between, parabola_vertex, zero_crossing

   !> The samples a peak is refined from (peak_sample, peak_between).
   type :: peak_track_t
      integer :: samples = 0              !< samples taken so far
      real(dp) :: t_last = 0.0_dp         !< time of the last sample (s)
      real(dp) :: v_last = 0.0_dp         !< its value
      real(dp) :: t(3) = 0.0_dp           !< times of the sample before the largest, the largest, the one after (s)
      real(dp) :: v(3) = 0.0_dp           !< their values
      logical :: before = .false.         !< there is a sample before the largest (t(1), v(1))
      logical :: after = .false.          !< there is a sample after the largest (t(3), v(3))
   end type peak_track_t

contains

   !> The vertex (tv, vv) of the parabola through (t(k), v(k)), k = 1..3, t
   !> increasing; concave false (the middle sample) when it does not open
   !> downwards, a sample is not finite, or the vertex is outside [t(1), t(3)].
   pure subroutine parabola_vertex(t, v, tv, vv, concave)
      real(dp), intent(in) :: t(3)              !< the samples' times, increasing
      real(dp), intent(in) :: v(3)              !< their values
      real(dp), intent(out) :: tv               !< the vertex's time
      real(dp), intent(out) :: vv               !< its value
      logical, intent(out) :: concave           !< the vertex is a maximum between t(1) and t(3)
      real(dp) :: d1, d2, c
      tv = t(2)
      vv = v(2)
      concave = .false.
      if (.not. (all(ieee_is_finite(t)) .and. all(ieee_is_finite(v)))) return
      if (.not. (t(1) < t(2) .and. t(2) < t(3))) return
      d1 = (v(2) - v(1))/(t(2) - t(1))
      d2 = (v(3) - v(2))/(t(3) - t(2))
      c = (d2 - d1)/(t(3) - t(1))
      if (.not. c < 0.0_dp) return
      tv = 0.5_dp*(t(1) + t(2)) - d1/(2.0_dp*c)
      if (tv < t(1) .or. tv > t(3)) then
         tv = t(2)
         return
      end if
      ! about the middle sample: v = v2 + s (t - t2) + c (t - t2)^2, s its slope there
      vv = v(2) + (d1 + c*(t(2) - t(1)))*(tv - t(2)) + c*(tv - t(2))**2
      concave = .true.
   end subroutine parabola_vertex

   !> Where the line through (t1, y1) and (t2, y2), t1 < t2, is 0, kept in
   !> [t1, t2] (t2 when y1 = y2 or both are of one sign, t1 when y1 is 0).
   pure real(dp) function zero_crossing(t1, y1, t2, y2) result(tz)
      real(dp), intent(in) :: t1                !< the first sample's time
      real(dp), intent(in) :: y1                !< its value
      real(dp), intent(in) :: t2                !< the second sample's time (> t1)
      real(dp), intent(in) :: y2                !< its value
      tz = t2
      if (y1 /= y2) tz = min(max(t1 + (t2 - t1)*y1/(y1 - y2), t1), t2)
   end function zero_crossing

   !> Takes the sample (t, v): the largest when it exceeds the largest so far
   !> or is a NaN (which stays); its neighbours before and after are kept.
   pure subroutine peak_sample(p, t, v)
      type(peak_track_t), intent(inout) :: p    !< the samples kept
      real(dp), intent(in) :: t                 !< the sample's time (s)
      real(dp), intent(in) :: v                 !< its value
      if (p%samples == 0) then
         p%t(2) = t
         p%v(2) = v
      else if (ieee_is_nan(p%v(2))) then
         continue                               ! a NaN stays the largest
      else if (ieee_is_nan(v) .or. v > p%v(2)) then
         p%t(1) = p%t_last
         p%v(1) = p%v_last
         p%before = .true.
         p%t(2) = t
         p%v(2) = v
         p%after = .false.
      else if (.not. p%after) then
         p%t(3) = t
         p%v(3) = v
         p%after = .true.
      end if
      p%samples = p%samples + 1
      p%t_last = t
      p%v_last = v
   end subroutine peak_sample

   !> The largest value, refined (parabola_vertex), and its time; the largest
   !> sample itself at the ends or where not concave.
   pure subroutine peak_between(p, t_peak, v_peak)
      type(peak_track_t), intent(in) :: p       !< the samples kept
      real(dp), intent(out) :: t_peak           !< time of the peak (s)
      real(dp), intent(out) :: v_peak           !< the peak
      logical :: concave
      t_peak = p%t(2)
      v_peak = p%v(2)
      if (p%before .and. p%after) call parabola_vertex(p%t, p%v, t_peak, v_peak, concave)
   end subroutine peak_between

end module step_peak
