// The suction–irrigation cannula of a laparoscopy session (issue 19 §3): a SessionRunner part
// kept apart from the step loop in session_runner.cpp. The physics is in suction_irrigation.h
// and simulator/fluid (the jet, the pool).
#include "simulator/session/session_runner.h"

namespace viscera::sim {

void SessionRunner::irrigate(double dt) {
  // The blood of the bleeding sources runs down to the pool; the report's blood loss stays the
  // sources' own count (what suction draws off was lost all the same).
  double bled = 0.0;
  if (bleeding_)
    for (const fluid::BleedingSource& source : bleeding_->sources())
      bled += source.bled;
  irrigation_->follow(state_, world_, dt, bled, *report_.laparoscopy);
}

}  // namespace viscera::sim
