// The unit and one-line meaning of every field the scenario loader reads. Types, ranges and
// defaults come from the loader itself (spec/field_log.h); tests/sim/output_formats_test.cpp
// fails when a field is read but not here, or here but never read. Elements of a list ("[]" at
// the end of a path) are described by the list.
#include "spec/schema.h"

namespace canopy::spec {

const std::vector<FieldDoc>& fieldDocs() {
  static const std::vector<FieldDoc> docs = {
      {"name", "", "the scenario's name (outputs go to out/NAME)"},
      {"description", "", "one line shown by `canopy list`"},
      {"seed", "", "seed of every random stream (`--seed` replaces it)"},
      {"aoi", "m", "area of interest [x_min, y_min, x_max, y_max]; everything starts inside it"},
      {"clock", "", "the simulation clock"},
      {"clock.dt", "s", "time step"},
      {"clock.duration", "s", "length of the run (steps = duration / dt + 1)"},
      {"sensing", "", "team-wide sensing settings"},
      {"sensing.occlusion_model", "",
       "canopy: hidden strictly under a crown; line_of_sight: hidden when the segment from the "
       "UAV's ground point crosses a crown; volumes: hidden when the 3-D segment from the camera "
       "(a UAV's altitude, a ground robot's 0.5 m) to the walker's head (1.7 m) crosses a crown's "
       "volume (its outline from crown_base to crown_top, a wall's to its height), for every "
       "camera"},
      {"sensing.p_detect", "", "probability that a visible target is detected"},
      {"sensing.clutter_rate", "1/scan", "expected false detections per scan (Poisson)"},
      {"sensing.clutter_label", "", "label given to false detections"},
      {"sensing.truth_noise_scale", "", "simulated noise is drawn from N(0, scale · R)"},
      {"sensing.tree_radius_sigma", "m", "σ of the measured crown radius"},
      {"uavs", "", "the agents, UAVs and ground robots (at least one)"},
      {"uavs[].name", "", "the agent's name (default uavN)"},
      {"uavs[].kind", "",
       "uav: flies, any velocity up to v_max, camera looking down; ground: drives as a unicycle "
       "(turns toward the command at turn_rate, then drives), camera looking forward, sees by "
       "line of sight whatever sensing.occlusion_model says"},
      {"uavs[].turn_rate", "rad/s", "ground robots: the largest turn rate ω_max"},
      {"uavs[].start", "m", "start position [x, y] (default: the path's position at t = 0)"},
      {"uavs[].path", "",
       "a scripted path (followed when planner.algorithm is none): waypoints, velocity or track"},
      {"uavs[].path.waypoints", "",
       "[{\"t\": s, \"p\": [x, y]}, …], times increasing, linear in between"},
      {"uavs[].path.waypoints[].t", "s", "time of the waypoint"},
      {"uavs[].path.waypoints[].p", "m", "position of the waypoint"},
      {"uavs[].path.waypoints[].z", "m",
       "altitude at the waypoint (a UAV, issue 53): the altitudes the waypoints give, linear in "
       "time between them and held before the first and after the last, flown within climb_rate "
       "(late where steeper) and within [z_min, z_max], which must hold them; z defaults to the "
       "altitude at t = 0, z_min and z_max to the lowest and highest of z and the waypoints'"},
      {"uavs[].path.start", "m", "constant-velocity path: position at t = 0"},
      {"uavs[].path.velocity", "m/s", "constant-velocity path: velocity [vx, vy]"},
      {"uavs[].path.track", "s, m",
       "[[t, x, y], …] rows, or the name of a CSV file of t,x,y rows; a UAV's inline row may be "
       "[t, x, y, z], z an altitude as a waypoint's z"},
      {"uavs[].yaw", "rad", "heading ψ, or \"velocity\" to face the direction of flight"},
      {"uavs[].v_max", "m/s", "top speed; every command is clamped to it"},
      {"uavs[].radius", "m",
       "the agent's body, a disc (default 0.5 for a ground robot, 0 for a UAV): a ground "
       "robot's is stopped by trunks, walls and other robots; a UAV flies above them and keeps "
       "the sum of the two radii from every other UAV with a radius; 0: no body, it touches "
       "nothing (UAVs by default pass over one another, as in the paper's scenarios); 0 or 0.01 "
       "to 100 m (0.01 m: Box2D's b2_polygonRadius, the skin its collision keeps; a smaller "
       "body's mass overflows a float)"},
      {"uavs[].fov", "",
       "camera footprint: {\"size\": [w, h]} (w along the heading) or {\"radius\": r}; a ground "
       "robot's: {\"range\": r, \"angle\": θ}, a sector opening θ about the heading"},
      {"uavs[].fov.size", "m", "rectangular footprint [w, h]"},
      {"uavs[].fov.radius", "m", "disc footprint radius"},
      {"uavs[].fov.range", "m", "ground robots: how far the forward camera sees"},
      {"uavs[].fov.angle", "rad", "ground robots: the field of view's full angle, at most 2π"},
      {"uavs[].quality", "", "α_i, scales the whole measurement covariance R"},
      {"uavs[].r0", "m", "floor of the range d in R(z, p_i)"},
      {"uavs[].z", "m",
       "altitude (default 20 m, the altitude at which fov.size is the footprint; with a scripted "
       "path's z, that path's altitude at t = 0); any of z, z_min, z_max, climb_rate, camera or "
       "a path's z makes the UAV fly at a chosen altitude: its footprint follows from altitude "
       "and camera, its noise grows with the slant distance, the record writes its z"},
      {"uavs[].z_min", "m",
       "lowest altitude (default z: fixed; with a scripted path's z, the lowest of z and the "
       "path's)"},
      {"uavs[].z_max", "m",
       "highest altitude (default z: fixed; with a scripted path's z, the highest of z and the "
       "path's); z_min < z_max lets the planner choose the climb"},
      {"uavs[].climb_rate", "m/s", "largest climb or descent rate |ż|"},
      {"uavs[].camera", "", "a pinhole camera: fields of view and pitch (default: the angles that "
                            "make fov.size the nadir footprint at 20 m)"},
      {"uavs[].camera.hfov", "rad", "horizontal field of view, across the heading, below π"},
      {"uavs[].camera.vfov", "rad", "vertical field of view, along the heading, below π"},
      {"uavs[].camera.pitch", "rad",
       "the optical axis tilted forward from nadir (0); pitch + vfov/2 ≤ 80°: a trapezoid ahead"},
      {"targets", "", "the people to track"},
      {"targets[].name", "", "the target's name (default TN)"},
      {"targets[].label", "", "the target's class label (never \"tree\")"},
      {"targets[].path", "",
       "its scripted path: waypoints, velocity, track or footpaths (required)"},
      {"targets[].path.waypoints", "",
       "[{\"t\": s, \"p\": [x, y]}, …], times increasing, linear in between"},
      {"targets[].path.waypoints[].t", "s", "time of the waypoint"},
      {"targets[].path.waypoints[].p", "m", "position of the waypoint"},
      {"targets[].path.start", "m", "constant-velocity path: position at t = 0"},
      {"targets[].path.velocity", "m/s", "constant-velocity path: velocity [vx, vy]"},
      {"targets[].path.track", "s, m",
       "[[t, x, y], …] rows, or the name of a CSV file of t,x,y rows"},
      {"targets[].path.footpaths", "",
       "footpath walk: a layout file with footpaths (as `canopy import` writes), named as an "
       "include is; the person walks the network from the point nearest `from`"},
      {"targets[].path.from", "m", "footpath walk: the person starts at the network point nearest this"},
      {"targets[].path.to", "m",
       "footpath walk: walks the shortest route to the network point nearest this, then stays; "
       "absent: a random walk"},
      {"targets[].path.speed", "m/s", "footpath walk: walking speed"},
      {"targets[].path.seed", "",
       "footpath random walk: its seed (at each junction a uniformly drawn branch, never back "
       "unless at a dead end)"},
      {"occluders", "",
       "tree crowns: explicit trees, generators and {\"include\": \"layouts/file.json\"}"},
      {"occluders[].type", "", "disc, polygon, poisson, grid or cluster"},
      {"occluders[].include", "",
       "a layout file (a list of occluders, or {\"occluders\": […]}) inside the scenario's folder "
       "tree or the library"},
      {"occluders[].centre", "m", "disc: centre"},
      {"occluders[].trunk_radius", "m",
       "the solid trunk at the centre of each tree of the entry, which stops ground robots "
       "(crowns never do); at most the crown's radius. Absent: a disc's is 0.1 × its radius, "
       "clamped to [0.05, 0.5] m, and a polygon is a wall, solid throughout"},
      {"occluders[].radius", "m",
       "disc: radius; poisson, grid, cluster: a radius or [min, max] drawn uniformly"},
      {"occluders[].vertices", "m",
       "polygon: its vertices [[x, y], …] in order, either way round: 3 to 8 convex ones (a crown "
       "or wall), or up to 1024 of any simple polygon, concave allowed, no self-crossing (a wall "
       "cut into convex pieces, docs/gis-import.md)"},
      {"occluders[].crown_base", "m",
       "height of the crowns' lowest point (default 0: from the ground); the volumes occlusion "
       "model sees under it"},
      {"occluders[].crown_top", "m", "height of the crowns' top (default: above any UAV)"},
      {"occluders[].height", "m", "a wall's height (default: above any UAV)"},
      {"occluders[].region", "m",
       "poisson, cluster: [x_min, y_min, x_max, y_max] (default the AOI)"},
      {"occluders[].lambda", "1/m²", "poisson: trees per m²"},
      {"occluders[].seed", "", "generator's seed"},
      {"occluders[].min_gap", "m",
       "poisson, cluster: least gap between crowns (Matérn type-II thinning)"},
      {"occluders[].origin", "m", "grid: the first tree's centre"},
      {"occluders[].spacing", "m", "grid: [along a row, between rows]"},
      {"occluders[].rows", "", "grid: number of rows"},
      {"occluders[].cols", "", "grid: trees per row"},
      {"occluders[].angle", "rad", "grid: rotation about the origin"},
      {"occluders[].jitter", "m", "grid: uniform displacement of each tree, at most this far"},
      {"occluders[].parent_lambda", "1/m²", "cluster: cluster centres per m²"},
      {"occluders[].mean_trees", "", "cluster: mean trees per cluster (Poisson)"},
      {"occluders[].spread", "m", "cluster: σ of trees about their centre (Thomas process)"},
      {"tracking", "", "each agent's JIPDA tracker"},
      {"tracking.sigma_a", "m/s²", "NCV process-noise intensity σ_a"},
      {"tracking.gate_probability", "", "P_G of the χ²₂ association gate"},
      {"tracking.birth_gate_probability", "",
       "a measurement outside every track's gate at this probability starts a track"},
      {"tracking.p_detect", "", "P_D assumed by the tracker (times P(visible) per track)"},
      {"tracking.clutter_density", "1/m²",
       "spatial density λ of false detections assumed by the JPDAF"},
      {"tracking.max_hypotheses", "", "exact joint-event enumeration up to this many events"},
      {"tracking.birth_velocity_sigma", "m/s", "σ of a newborn track's velocity"},
      {"tracking.confirm_hits", "", "a track is confirmed after this many hits …"},
      {"tracking.confirm_window", "",
       "… within its first this many scans (default max(3, confirm_hits))"},
      {"tracking.delete_trace", "m²", "delete a track when tr(P_pos) exceeds this"},
      {"tracking.delete_misses", "",
       "> 0: also delete after this many misses while expected visible"},
      {"tracking.preseed", "", "start every agent with a confirmed track per target"},
      {"tracking.preseed_variance", "m², m², m²/s², m²/s²", "diagonal of a pre-seeded track's P₀"},
      {"tracking.tree_min_radius", "m", "a tree estimate's radius never goes below this"},
      {"tracking.confirmation", "",
       "existence (JIPDA thresholds) or m_of_n (confirm_hits of confirm_window)"},
      {"tracking.survival_probability", "",
       "probability that a target still exists 1 s later (per scan: this^dt; trees: 1)"},
      {"tracking.birth_existence", "", "probability of existence of a newborn track"},
      {"tracking.confirm_existence", "",
       "existence: confirmed once existence reaches this; at least delete_existence"},
      {"tracking.delete_existence", "",
       "existence: deleted once existence falls below this; at most birth_existence (else every "
       "newborn track is dropped at birth) and at most confirm_existence"},
      {"tracking.merge_gate", "",
       "χ²₄ gate on the track-to-track distance Δxᵀ(P_a + P_b)⁻¹Δx of two duplicates"},
      {"tracking.merge_scans", "",
       "duplicates merged after this many consecutive scans that pass the duplicate test (0: "
       "never)"},
      {"tracking.merge_distance", "m",
       "duplicates: both confirmed with tr(P_pos) ≤ 2·this², means within this, updated by one "
       "detection of the own scan"},
      {"tracking.walk_speed", "m/s",
       "a known (pre-seeded) person's speed at most: bounds the velocity of a lost track, which "
       "is never deleted"},
      {"tracking.negative_information", "",
       "a target track that a scan gives no measurement loses the probability mass its camera "
       "would have seen (P_D × P_G of it), moment-matched; false: it keeps its prediction"},
      {"fusion", "", "consensus fusion between agents"},
      {"fusion.method", "", "ci, hcmci or observer_average"},
      {"fusion.rounds", "", "L consensus rounds per step"},
      {"fusion.comm_range", "m", "agents within this distance exchange messages; null: unlimited"},
      {"fusion.interest_range", "m",
       "after each fusion step an agent forgets target tracks and trees farther than this from it; "
       "null: keeps everything"},
      {"fusion.comm_drop", "", "probability that a message is lost"},
      {"fusion.comm_latency", "steps",
       "simulation steps every message is in flight: consensus messages (a receiver fuses what "
       "its neighbours held that many steps ago, predicted to now) and intentions (plans, orders)"},
      {"fusion.association_gate", "",
       "χ²₂ gate on the position Mahalanobis distance when matching tracks across agents"},
      {"planner", "", "nominal belief planning"},
      {"planner.algorithm", "",
       "none (scripted paths), sma, dec_pomdp, centralized or learned (a network imitating "
       "SMA-NBO; docs/imitation.md)"},
      {"planner.policy", "",
       "learned: the policy file (docs/imitation.md); default: the scenario library's "
       "policies/NAME.json for the scenario's name, else policies/trajectory_handover.json"},
      {"planner.horizon", "", "H, planned actions"},
      {"planner.plan_period", "s", "Δ, the length of each planned action"},
      {"planner.replan_period", "s",
       "time between decision epochs, a whole multiple of dt, at most plan_period (default "
       "plan_period)"},
      {"planner.occlusion_map", "",
       "the occlusion map the cost uses: a_priori (the true crowns), dynamic (crowns seen so far) "
       "or none"},
      {"planner.discount", "", "γ, discount per action"},
      {"planner.cost_trace", "",
       "position (tr P_pos), full (tr P) or custody (exp(−r²/tr P_pos): the probability that a "
       "track is more than custody_radius off)"},
      {"planner.custody_radius", "m",
       "cost_trace custody: the distance r within which a track holds its person (the team "
       "measure's 5 m by default)"},
      {"planner.terminal_penalty", "", "add w × the distance to the tracks at the horizon's end"},
      {"planner.terminal_penalty_weight", "", "w of the terminal penalty"},
      {"planner.clearance", "m",
       "ground robots: a nominal path closer than radius + clearance to a trunk or wall of the "
       "agent's map, or than the sum of the radii + clearance to another robot's intended path "
       "(UAVs with a radius: to another such UAV's), is charged a penalty that forbids it "
       "(docs/design-notes.md)"},
      {"planner.cost_scope", "",
       "team (the paper's cost: every track, every UAV) or reach (only the tracks a free UAV can "
       "reach within the horizon and the teammates that can reach them; an approximation of the "
       "terminal penalty, docs/design-notes.md)"},
      {"planner.cost_substeps", "",
       "samples of the nominal trajectory per action (1: the paper's cost)"},
      {"planner.joint_search", "",
       "dec_pomdp and centralized: block_coordinate (one swarm per UAV's part of the joint plan in "
       "turn, every evaluation the joint cost), global_best (the paper's one swarm) or local_best "
       "(one ring swarm with warm starts and restarts)"},
      {"planner.joint_rounds", "", "block_coordinate: rounds over all UAVs"},
      {"planner.joint_blocks", "",
       "Dec-POMDP's block_coordinate: each agent optimises the blocks of the UAVs that can "
       "interact with it within the horizon (interacting) or of every UAV (all)"},
      {"planner.order", "",
       "block_coordinate: the UAVs' order (names or indices; default their order)"},
      {"pso", "", "the particle swarm of every planner"},
      {"pso.particles_per_step", "", "particles = this × H"},
      {"pso.inertia", "", "w, inertia weight"},
      {"pso.c1", "", "cognitive weight"},
      {"pso.c2", "", "social weight"},
      {"pso.ftol", "", "relative change of the best cost counted as a stall"},
      {"pso.stall_iterations", "", "stop after this many stalled iterations in a row"},
      {"pso.max_iterations", "", "hard cap on iterations"},
      {"pso.warm_start", "", "one particle starts at the previous plan, shifted"},
      {"analysis", "", "what `canopy analyze` looks for"},
      {"analysis.m", "", "m of m-ownership: steps a target must stay in a UAV's footprint"},
      {"analysis.oa_margin", "s",
       "margin on both sides of an occluded interval (Occlusion_Aware windows)"},
      {"analysis.states", "",
       "named ownership states, e.g. {\"name\": \"M*\", \"sets\": [[\"I\"], [\"II\", \"III\"]]}"},
      {"analysis.states[].name", "", "the state's name"},
      {"analysis.states[].sets", "", "per UAV, the targets it owns (names or indices)"},
      {"analysis.states[].any_permutation", "",
       "true: the sets may belong to the UAVs in any order"},
  };
  return docs;
}

}  // namespace canopy::spec
