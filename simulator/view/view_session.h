#pragma once
/// Sessions shown in the endoscopic view (issue 8 points 1, 6, 7): in a window in real time,
/// driven by a scripted or recorded input or by the keyboard and mouse; offscreen at full speed
/// for a snapshot; and a replay rendered frame by frame into an Ogg Theora video. The session
/// steps exactly as headless (the view only reads snapshots of it), so every trace replays
/// bit-identically.

#include <filesystem>
#include <string>

#include "core/scenario/scenario.h"
#include "simulator/input/live_input.h"
#include "simulator/session/manual_control.h"
#include "simulator/session/session_runner.h"
#include "simulator/view/endoscopic_view.h"

namespace viscera::view {

/// Runs the session in the view's window in real time until it ends or the window closes
/// (closing ends it as "abort"). With options.instrument the recorded or scripted input drives
/// the instrument; otherwise `live` does (a gamepad, a device over UDP), or, without it,
/// `manual` through the keyboard. The window's keys and mouse always feed `manual` (when
/// given), so the keyboard works beside a gamepad. Threaded (sim::RealtimeLoop): the physics
/// steps the SessionRunner on its own thread at the scenario's step, a device's I/O runs on
/// its own at ≥ 1 kHz, and this thread draws the newest snapshot every 1/`frame_rate` s.
/// The report's `realtime` says how it kept time (frames, lag, device feedback). Throws the
/// physics thread's core::SimulationError after closing the window.
sim::SessionReport run_in_window(const core::Scenario& scenario,
                                 const sim::HeadlessRunOptions& options, EndoscopicView& view,
                                 sim::ManualControl* manual, sim::LiveInput* live = nullptr,
                                 double frame_rate = 60.0);

/// Runs the session at full speed (as headless) and writes the view's frame at simulated time
/// `at` s (negative: after the end) to `png`. Throws core::OutputError when it cannot write.
sim::SessionReport run_with_snapshot(const core::Scenario& scenario,
                                     const sim::HeadlessRunOptions& options, EndoscopicView& view,
                                     const std::filesystem::path& png, double at = -1.0);

/// Runs the session at full speed and encodes one frame every 1/fps simulated seconds into an
/// Ogg Theora video at `ogv` (vtkOggTheoraWriter). Returns the report; `frames` receives the
/// number of frames written. Throws core::OutputError when the video cannot be written.
sim::SessionReport run_to_video(const core::Scenario& scenario,
                                const sim::HeadlessRunOptions& options, EndoscopicView& view,
                                const std::filesystem::path& ogv, int fps, long long& frames);

}  // namespace viscera::view
