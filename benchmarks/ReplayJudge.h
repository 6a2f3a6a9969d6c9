/* The one geometric rule bench_opende_peer judges both sides' replays by, whatever each side's own
   rules say. */
#pragma once

#include "OpenDEPeer.h"

#include <string>
#include <vector>

namespace opende_peer
{
    /** Deepest allowed overlap, m: resting soft contacts sink about ODE's surface layer (1 mm). */
    constexpr double PENETRATION_TOLERANCE = 0.005;
    /** Largest allowed lean of a body's up axis from vertical, rad: a pushed box tilts a few degrees. */
    constexpr double TIP_TOLERANCE = 15.0 * M_PI / 180.0;

    /** Judges the states of every moving body: the robot must not be inside a fixed body, and a
        movable body must neither sink into a fixed body or the floor nor tip over (a box's or
        cylinder's up axis leaning more than TIP_TOLERANCE; a rolling sphere has no up). Depths come
        from ODE's collision functions on the scene's geometry (a peer world that is never stepped).
        @pre ODE is initialised (dInitODE2). */
    class ReplayJudge
    {
    public:
        /** A judge for states of scene (shared). */
        explicit ReplayJudge(ompl_phys::PhysicsScenePtr scene);

        /** The first fault in states (robot first, then the movable bodies in scene order), or an
            empty string. */
        std::string fault(const ompl_phys::BodyStates &states) const;

    private:
        PeerEnvironment probe_;
        std::vector<bool> hasUp_;  // per movable body
    };
}  // namespace opende_peer
