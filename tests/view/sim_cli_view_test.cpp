// `viscera-sim` with its view: the snapshot of a run on a hysteroscopy package shows the organ,
// a headless run and a run without an X display refuse to render, and a replay renders to a
// valid Ogg Theora video with one frame per 1/fps simulated seconds while staying bit-identical.

#include <gtest/gtest.h>
#include <vtkImageData.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/json_eigen.h"
#include "simulator/session/manual_control.h"
#include "simulator/view/scene_surfaces.h"
#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"
#include "tests/view/view_fixtures.h"

namespace viscera {
namespace {

using testing::run_program;
using testing::shell_quote;

/// Packets of an Ogg stream: the lacing values below 255 that end one (RFC 3533 §6).
long long ogg_packets(const std::string& bytes, int& pages) {
  long long packets = 0;
  pages = 0;
  std::size_t at = 0;
  while (at + 27 <= bytes.size() && bytes.compare(at, 4, "OggS") == 0) {
    const auto segments = static_cast<unsigned char>(bytes[at + 26]);
    std::size_t body = 0;
    for (unsigned s = 0; s < segments; ++s) {
      const auto lacing = static_cast<unsigned char>(bytes[at + 27 + s]);
      body += lacing;
      if (lacing < 255) ++packets;
    }
    at += 27 + segments + body;
    ++pages;
  }
  return at == bytes.size() ? packets : -1;
}

/// A 1 s script on the patient: from the starting pose 4 mm along the line of sight.
std::filesystem::path write_script(const std::filesystem::path& dir) {
  const auto& patient = testing::hysteroscopy_patient();
  const double angle = patient.scenario.session.instrument.optics_angle;
  const sim::InstrumentState start = sim::starting_pose(patient.scenario, angle);
  const core::Vec3 view = sim::view_direction(start, angle);
  const nlohmann::json script = {
      {"format", "viscera-script"},
      {"version", 2},
      {"waypoints",
       {{{"t", 0.0}, {"tip", start.tip}, {"axis", start.axis}, {"up", start.up}},
        {{"t", 1.0},
         {"tip", core::Vec3(start.tip + 0.004 * view)},
         {"axis", start.axis},
         {"up", start.up}}}}};
  const auto path = dir / "script.json";
  std::ofstream(path) << script.dump(2);
  return path;
}

TEST(SimCliView, run_writes_a_snapshot_of_the_endoscopic_view) {
  const auto& patient = testing::hysteroscopy_patient();
  const auto dir = testing::scratch_dir();
  const auto png = dir / "view.png";
  const auto result =
      run_program("viscera-sim",
                  "run " + shell_quote(patient.package.string()) + " --script " +
                      shell_quote(write_script(dir).string()) + " --snapshot " +
                      shell_quote(png.string()) + " --snapshot-time 0.5 --width 640 --height 360",
                  dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("snapshot "), std::string::npos) << result.out;
  const auto frame = view::decode_png(viscera::testing::file_bytes(png), png.string());
  int dims[3];
  frame->GetDimensions(dims);
  EXPECT_EQ(dims[0], 640);
  EXPECT_EQ(dims[1], 360);
  const auto stats = testing::frame_statistics(frame, 0.9);
  EXPECT_GT(stats.lit_fraction, 0.8);
  EXPECT_GT(stats.luminance_stddev, 4.0);
  EXPECT_LT(testing::corner_luminance(frame), 1.0) << "the round field stop of the optics";
}

TEST(SimCliView, headless_runs_refuse_to_render_with_exit_2) {
  const auto& patient = testing::hysteroscopy_patient();
  const auto dir = testing::scratch_dir();
  const auto result = run_program("viscera-sim",
                                  "run " + shell_quote(patient.package.string()) +
                                      " --headless --snapshot x.png --duration 0.01",
                                  dir);
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

TEST(SimCliView, without_an_x_display_a_snapshot_is_refused_in_one_sentence_not_a_crash) {
  // VTK ends the process when it cannot reach the display; the view asks first (x_display.h).
  const auto& patient = testing::hysteroscopy_patient();
  const auto dir = testing::scratch_dir();
  const char* display = std::getenv("DISPLAY");
  const std::string saved = display != nullptr ? display : "";
  ::unsetenv("DISPLAY");
  const auto result = run_program(
      "viscera-sim",
      "run " + shell_quote(patient.package.string()) + " --snapshot x.png --duration 0.01", dir);
  if (!saved.empty()) ::setenv("DISPLAY", saved.c_str(), 1);
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_NE(result.err.find("DISPLAY is not set"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

TEST(SimCliView, replay_renders_an_ogg_theora_video_and_stays_identical) {
  const auto& patient = testing::hysteroscopy_patient();
  const auto dir = testing::scratch_dir();
  const auto trace = dir / "trace.json";
  auto result = run_program("viscera-sim",
                            "run " + shell_quote(patient.package.string()) +
                                " --headless --script " + shell_quote(write_script(dir).string()) +
                                " --record " + shell_quote(trace.string()),
                            dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto video = dir / "replay.ogv";
  result = run_program("viscera-sim",
                       "replay " + shell_quote(trace.string()) + " --video " +
                           shell_quote(video.string()) + " --fps 10 --width 320 --height 240",
                       dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("replay identical"), std::string::npos) << result.out;
  const std::size_t at = result.out.find("(", result.out.find("video "));
  ASSERT_NE(at, std::string::npos) << result.out;
  const long long frames = std::stoll(result.out.substr(at + 1));
  const std::string bytes = viscera::testing::file_bytes(video);
  ASSERT_GT(bytes.size(), 100u);
  EXPECT_EQ(bytes.compare(0, 4, "OggS"), 0);
  EXPECT_EQ(bytes.compare(28, 7, "\x80theora"), 0) << "the first packet is Theora's header";
  int pages = 0;
  const long long packets = ogg_packets(bytes, pages);
  // A 1 s session at 10 fps: the first frame and one per 0.1 s; three Theora header packets.
  EXPECT_EQ(frames, 11);
  EXPECT_EQ(packets, frames + 3) << pages << " pages";
  EXPECT_FALSE(std::filesystem::exists(dir / "replay.ogv.partial"));
}

TEST(SimCliView, a_window_session_runs_in_real_time_and_its_trace_replays) {
  const auto& patient = testing::hysteroscopy_patient();
  const auto dir = testing::scratch_dir();
  const auto trace = dir / "window.json";
  const auto start = std::chrono::steady_clock::now();
  auto result = run_program("viscera-sim",
                            "run " + shell_quote(patient.package.string()) +
                                " --duration 0.5 --width 320 --height 240 --record " +
                                shell_quote(trace.string()),
                            dir);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("ended: duration"), std::string::npos) << result.out;
  EXPECT_GE(wall, 0.5) << "the window paces the session at real time";
  // The manual control's states (the resting starting pose) are in the trace.
  result = run_program("viscera-sim", "replay " + shell_quote(trace.string()), dir);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("replay identical"), std::string::npos) << result.out;
}

}  // namespace
}  // namespace viscera
