#pragma once
// Waypoint export of a mission trace (docs/export.md): every UAV's flown trajectory compressed to
// waypoints (io/waypoints.hpp), placed in the ship frame (io/ship_frame.hpp), optionally
// geo-referenced (io/geo_reference.hpp), cut into sorties and mission files (io/sorties.hpp) and
// written as csv, a QGroundControl .plan, a `QGC WPL 110` file, a YAML nav_msgs/Path, a Litchi
// CSV mission, a DJI WPML wayline (KMZ) or a Google Earth KML preview.

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "hullinspect/io/geo_reference.hpp"
#include "hullinspect/io/ship_frame.hpp"
#include "hullinspect/io/sorties.hpp"
#include "hullinspect/io/waypoints.hpp"

namespace hullinspect::io {

enum class ExportFormat { kCsv, kQgc, kWpl, kPath, kLitchi, kDjiKmz, kKml };

/// "csv", "qgc", "wpl", "path", "litchi", "dji-kmz", "kml"; throws ParameterError("format") for
/// anything else.
ExportFormat parse_export_format(const std::string& name);
std::string_view to_string(ExportFormat format);
/// The formats named by the (repeatable) --format values; "all" names every format. Duplicates
/// are dropped, the order kept.
std::vector<ExportFormat> parse_export_formats(const std::vector<std::string>& names);
/// True for the flight formats that cannot carry no-fly positions truthfully (qgc, wpl, litchi,
/// dji-kmz: none has a vertical obstacle, and a horizontal fence would also forbid the legal
/// flight past it); kml draws them, csv and path list positions only.
bool drops_no_fly(ExportFormat format);
/// True for the formats that place waypoints on the Earth (they need a geo-reference).
bool needs_geo_reference(ExportFormat format);

/// The flight controller a MAVLink mission (qgc, wpl) is written for.
enum class Firmware { kPx4, kArduPilot };
/// What a sortie does after its last waypoint: land at its home point, or return-to-launch.
enum class FinishAction { kLand, kRtl };
/// DJI aircraft a WPML wayline declares (droneInfo and payloadInfo).
enum class DjiDrone { kM350, kM300, kM30, kM30T, kM3E };

/// "m350", "m300", "m30", "m30t", "m3e"; throws ParameterError("drone").
DjiDrone parse_dji_drone(const std::string& name);

/// How the files are cut and what they ask of the vehicle.
struct ExportSettings {
  Firmware firmware = Firmware::kPx4;  ///< the firmware a qgc or wpl file is written for
  /// The firmwares to write qgc and wpl files for; with more than one, each file's name says
  /// which (`uav<k>.px4.plan`, `uav<k>.ardupilot.plan`). Empty: `firmware` alone.
  std::vector<Firmware> firmwares;
  FinishAction finish = FinishAction::kLand;
  DjiDrone drone = DjiDrone::kM350;
  std::vector<grid::Cell> launch_sites;  ///< empty: each UAV takes off below its start position
  /// The launch sites' ground (where a sortie takes off and lands) at this height Z of the ship
  /// frame, metres; unset: the grid's bottom edge, Z0.
  std::optional<double> launch_height_m;
  /// The geoid's height above the WGS-84 ellipsoid at the ship, metres (N): the heights a format
  /// means above mean sea level are written h − N. Unset: none is, they stay ellipsoidal.
  std::optional<double> geoid_height_m;
  int max_waypoints = 0;  ///< 0: each format's default cap
  double simplify_m = 0;  ///< 0: no simplification (io/simplify.hpp)
  /// Per UAV, the sorties of a battery-limited mission (empty: one sortie per UAV). Each becomes
  /// its own mission files, `uav<k>_sortie<s>.<ext>` (plan_sorties).
  std::vector<std::vector<FlownSortie>> flown_sorties;
};

/// The default waypoint cap of a format (0 = none): Litchi 99 (its mission limit), DJI 200 (a
/// conservative limit for the remote controllers).
int default_waypoint_cap(ExportFormat format);

/// What every format writes: the frame, each UAV's waypoints and the mission's no-fly positions.
struct ExportPlan {
  ShipFrame frame;
  int plane_change_steps = 1;
  int width = 0;  ///< the grid
  int height = 0;
  std::vector<std::vector<ExportWaypoint>> uavs;  ///< per UAV, the trace's waypoints
  std::vector<std::vector<GridState>> states;     ///< per UAV, its state in every frame
  std::vector<grid::Cell> no_fly;
  std::vector<std::string> hull_rows;  ///< the trace's truth rows ('.' = not hull)
  double step_seconds = 1.0;           ///< the trace's step in seconds (docs/model.md)
  /// The mission's own launch sites (the trace's `launch`; empty without) and each UAV's.
  std::vector<grid::Cell> launch_sites{};
  std::vector<int> site_of{};
  bool battery_limited = false;  ///< the mission had an endurance (the trace's `battery`)
  /// The frame in which the hull became known and every UAV was turned home (a complete
  /// mission's first frame with its last `series.known`); -1 for an incomplete mission.
  int homing_frame = -1;
  /// A waypoint's time or duration in steps, in seconds.
  double seconds(int steps) const { return steps * step_seconds; }
  bool is_hull(grid::Cell c) const;
};

/// Builds the plan of a validated trace; `source` (the trace or hull file the geometry came from)
/// is named when a waypoint's coordinates cannot be represented.
ExportPlan export_plan(const nlohmann::json& trace, const std::string& source = "trace");

struct ExportFile {
  std::string name;  ///< file name inside the output directory
  std::string content;
};

/// The file of one mission part: `uav<k>.<ext>`, or `uav<k>-part<p>.<ext>` when a sortie was
/// split; a sortie cut from a battery-limited mission is `uav<k>_sortie<s>.<ext>`, split
/// `uav<k>_sortie<s>-part<p>.<ext>` (s and p from 1). Extensions: csv, plan (qgc), waypoints
/// (wpl), path.yaml, litchi.csv, kmz.
std::string mission_file_name(ExportFormat format, const MissionPart& part);

/// "px4", "ardupilot".
std::string_view to_string(Firmware firmware);

/// The files a mission part is written as in `format`: mission_file_name's, or for qgc and wpl
/// with several firmwares one per firmware, its name before the extension (`uav0.px4.plan`).
std::vector<std::string> mission_file_names(ExportFormat format, const MissionPart& part,
                                            const ExportSettings& settings);

/// The names of the files written for `uavs` UAVs when no sortie is split (known before any
/// mission runs, so a command can check its outputs first).
std::vector<std::string> export_file_names(ExportFormat format, int uavs, bool geo_referenced);

/// The files of one format. Every format but csv and path needs a geo-reference: without one
/// this throws ParameterError("origin").
std::vector<ExportFile> export_files(const ExportPlan& plan, ExportFormat format,
                                     const std::optional<GeoReference>& geo,
                                     const ExportSettings& settings);

/// The hold time (s) a flight controller waits at waypoint `w` so that a vehicle flying at the
/// plan's cruise speed between waypoints arrives at the trace's times: the hold's duration, or the
/// part of a plane change its straight flight does not take.
double hold_seconds(const ExportPlan& plan, const ExportWaypoint& w,
                    const ExportWaypoint& previous);

/// The cruise speed of an exported plan: one cell per step (model.md §1: a move takes one step),
/// in m/s.
double cruise_speed_mps(const ExportPlan& plan);

/// The distance between two photos that gives every cell a picture, as the model senses once per
/// step: one cell (consecutive footprints of s_z cells overlap by 1 − 1/s_z).
double photo_distance_m(const ExportPlan& plan);

}  // namespace hullinspect::io
