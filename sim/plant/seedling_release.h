#pragma once
// How a seedling comes to stand in the furrow: its release, from mechanics (the paper, Sec. 2
// and Fig. 5: the root is buried while the leaves are still held; the disc pushes the top
// backwards, F', and the returning soil pushes the root forwards, F).
//
// The seedling is a rigid rod (its length, diameter and the paper's density 870.5 kg/m^3),
// radial in the disc with its root end beyond the rim, in the plane of the row. At 0.06 m/s
// and 0.3 rad/s the accelerations are a thousandth of g, so each instant of the carry is
// quasi-static: the rod goes where the forces on it balance. The disc rides with the opener
// (the paper, Sec. 2.1, Fig. 2), so the root end's lowest point sits a set clearance above the
// furrow floor at any depth. Stages, integrated over the disc's angle:
//  0. Carried: both lip faces hold the seedling by friction, 2 mu N (Coulomb), against its
//     weight, the disc's centripetal acceleration and the belt's hand-off (its speed mismatch
//     taken up over the nip time). Less grip than that and it falls from the clamp: a skip.
//  1. Held: the root end follows the trochoid of radius R + protrusion at the actual v and
//     omega. Once below the surface it is dragged through the returned soil (the plowing force,
//     sim/soil/root_anchorage.h), against its motion. Across the rod, the lips resist turning
//     elastically, shearing the rubber under the contact (G, over its sheared layer), up to a
//     friction moment mu N w / 2 (N on each of two faces, uniform over the held length
//     w = contact area / diameter): when the soil's moment about the clamp is larger, the root
//     stays where the soil holds it and the seedling turns in the clamp (the paper, Sec. 4.3).
//     Along the rod, the same friction 2 mu N holds it: when the soil's axial share is larger,
//     the seedling slides in the clamp and its root ends up shallower or deeper.
//  2. Released: the lips open past the lowest point. The leaves still between them are
//     dragged with the disc's surface by friction mu N_res (F'). When that is more than the
//     buried root can hold (the free short pile, load at the lips' height), the seedling
//     turns about its root end with the lips; otherwise the lips slide over it. This lasts
//     until the rod's top leaves the disc's circle.
//  3. Standing: what the model leaves out is added as a scatter (crooked seedlings, the
//     machine's vibration). Then the rod stands on its root end in the returned soil: where its
//     weight's moment beats the soil's, it falls (rigid rod about its end, the soil's moment
//     resisting, integrated in time) until the covering wheel arrives (its distance behind the
//     release over the ground speed). The wheel fills the furrow to the surface and presses the
//     soil: from then the root is held over its whole burial by the firmed soil, and a seedling
//     whose weight still beats that lodges (90 deg); any other stops at the tilt it has.
// The root's end goes no deeper than the furrow floor. Left out: the soil's elastic give (about
// a millimetre), the rod's bending, the soil the covering wheel pushes against the stem, and the
// root's pull-out resistance along its axis beyond plowing.
#include "sim/plant/plant_config.h"

namespace planter::sim {

struct ReleaseInput {
  double length_mm = 0, diameter_mm = 0;
  double v_mps = 0;          // ground speed at release
  double omega_radps = 0;    // disc speed at release
  double depth_mm = 0;       // furrow depth
  double clamp_force_N = 0;  // the lips' force on the seedling while held
  double scatter_deg = 0;    // what the stages leave out, added before it stands (+ top forward)
};

struct ReleaseOutcome {
  double tilt_deg = 0;         // after covering, + top forward (90: lodged)
  double clamp_turn_deg = 0;   // turned in the clamp while held (stage 1)
  double lip_drag_deg = 0;     // turned by the lips after release (stage 2)
  double clamp_slip_mm = 0;    // slid along its axis in the clamp (+ root out further)
  double burial_mm = 0;        // root end's depth below the surface
  double fall_deg = 0;         // fallen under its weight before the covering wheel firmed it
  bool fell_in_carry = false;  // dropped from the clamp before it reached the soil: a skip
  bool lodged = false;
};

ReleaseOutcome release_seedling(const PlantConfig& config, const ReleaseInput& in);

// The held length of stem between the lips (m): contact area / diameter, at most the band of
// flexible protrusions.
double held_length_m(const MechanismConfig& mc, double diameter_mm);

// The lips' elastic stiffness against the seedling turning in the disc's plane (N m/rad): the
// rubber under both faces' contact patches in simple shear.
double lip_turning_stiffness_Nm_per_rad(const MechanismConfig& mc, double diameter_mm);

// The clamp force (N) below which a seedling of this size drops from the clamp during the
// carry at disc speed omega: its weight and accelerations over the two faces' friction.
double carry_grip_needed_N(const PlantConfig& config, double length_mm, double diameter_mm,
                           double omega_radps);

}  // namespace planter::sim
