#pragma once

#include "ompl_mm/collision/ConvexShape.h"
#include "ompl_mm/collision/MotionBounds.h"
#include "ompl_mm/model/ManipulationModel.h"

#include <fcl/fcl.h>

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ompl_mm
{
    /** Makes the FCL geometry of a shape (cylinders along z, centred); the caller shares its
        ownership. A mesh becomes, as meshes asks, a bounding-volume hierarchy (OBBRSS) of its
        triangles or the convex polytope of its hull (TriangleMesh::convexHull(), computed once per
        mesh), which holds the mesh (to within ConvexHull::RELATIVE_TOLERANCE) and whose distance
        queries run GJK on its corners instead of walking the triangles.
        @throws ompl::Exception for a shape kind outside Shape::Kind, or naming the mesh file when
        its hull is asked for and its vertices span no volume (a flat mesh). */
    std::shared_ptr<fcl::CollisionGeometryd> makeCollisionGeometry(
        const Shape &shape, MeshCollision meshes = MeshCollision::Exact);

    /** Collision checking of one manipulation configuration with FCL: robot links, movable
        objects and the fixed obstacles (in a broad-phase tree). It applies the contact rules of the
        state-based validity: a held object may touch the gripper (the tool link, the links below
        it and the scene's gripper links), a resting object may touch the obstacle its surface belongs to,
       listed robot link pairs are ignored, adjacent links never collide with each other, and neither do links
       that touch in the zero pose and in at least ALWAYS_TOUCHING_SHARE of SELF_CHECK_POSES random poses
        (they are built to touch, like an SRDF's "default" and "always" pairs; listed with
        OMPL_INFORM). Robot link meshes collide as the scene's RobotSpec::meshCollision says (the
        robot attribute meshes="exact" or "convex_hull"): as their triangles (a surface: a body
        wholly inside one does not touch it), or as their solid convex hulls, whose distance queries
        (checkSweep's rounds) skip the triangle hierarchy but which fill the meshes' concavities,
        so they reject some free configurations and accept none where the triangles collide. Not
        thread-safe: queries move the bodies. Not copyable (FCL objects hold raw pointers). */
    class CollisionWorld
    {
    public:
        /** A configuration to check: joint values, and per object its pose and resting surface
            (-1 = held by the robot); optionally only some of the bodies. */
        struct Configuration
        {
            const double *joints{nullptr};                     ///< one value per moving joint; null: no robot
            const std::vector<ObjectPose> *objects{nullptr};   ///< one pose per object, world frame
            const std::vector<int> *restingSurfaces{nullptr};  ///< per object, its surface index or -1
            const std::vector<char> *present{nullptr};         ///< per object, 0 to leave it out; null: all
        };

        /** Builds the bodies of the model's robot, objects and obstacles; shares the model.
            @throws ompl_core::InputError when a surface names an unknown obstacle or an allowed
            collision pair names an unknown link, or at the scene's robot element when convex hulls are
            asked for and a link's mesh spans no volume (naming the link and the mesh file). */
        explicit CollisionWorld(ManipulationModelPtr model);
        /** Frees the FCL bodies. */
        ~CollisionWorld();
        CollisionWorld(const CollisionWorld &) = delete;             ///< not copyable
        CollisionWorld &operator=(const CollisionWorld &) = delete;  ///< not copyable

        /** True when nothing collides. When it returns false and contact is given, contact names
            the first colliding pair ("robot link 'a'", "object 'b'", "obstacle 'c'").
            @pre the configuration's pointers are set and sized for the model. */
        bool isCollisionFree(const Configuration &configuration, std::string *contact = nullptr) const;

        /** The first contact among some bodies, for checks before planning (of a start or of goal
            poses): the robot at joints (left out when null) and the objects whose pose is given
            (nullopt: left out), each resting on the surface that supports it or held if none does;
            empty when they are collision-free. */
        std::string contactAmong(const double *joints,
                                 const std::vector<std::optional<ObjectPose>> &objects) const;

        /** Least distance between bodies that move relative to each other along a motion, metres. */
        static constexpr double MIN_CLEARANCE = 1e-5;
        /** How far below the distance of two convex solids convexDistance() may stop, metres (its
            results are lower bounds). */
        static constexpr double DISTANCE_ERROR = 0.25 * MIN_CLEARANCE;
        /** Clearance a motion keeps at the fraction it reports as safe (SweepCheck), metres: a
            planner that stops there can leave again without grazing. */
        static constexpr double SAFE_CLEARANCE = 1e-2;
        /** Most distance rounds of one motion check; a motion that grazes a body so closely that it
            needs more is rejected. */
        static constexpr unsigned int MAX_SWEEP_ROUNDS = 4000;

        /** The outcome of a continuous motion check. */
        struct SweepCheck
        {
            bool free;            ///< every configuration along the motion is collision-free
            double safeFraction;  ///< a fraction of the way up to which it is free, with SAFE_CLEARANCE there
            /** The movable object in the contact that stopped the motion (of two, the one the motion
                moves less), or -1: free, or stopped by the robot itself or an obstacle alone. */
            int blockingObject{-1};
            /** The two bodies whose contact stopped the motion ("robot link 'hand'", "object 'cyl1'"),
                views of the world's labels; empty when free, or stopped by grazing too long. */
            std::string_view contact[2]{};
            /** The check was stopped (its stop callback said so) before it finished: not free, and
                no contact to blame; safeFraction holds for the rounds it did. */
            bool interrupted{false};
        };

        /** Continuous collision check of a motion from one configuration to another, under the
            contact rules of isCollisionFree (a contact allowed at both ends is allowed along the
            motion; an object put down on an obstacle or lifted off it may touch it only where it
            rests on it): conservative advancement, each round measuring the
           distances of the body pairs that may meet and advancing as far as their sweeps (MotionBounds)
           cannot close them. So a motion it accepts is free at every point, and any part of it is accepted as
           well, to within the distances' precision (DISTANCE_ERROR for convex solids, measured by
            convexDistance(); FCL's for triangle meshes) and MAX_SWEEP_ROUNDS. The joints must move linearly
            and each object slide or be carried with the tool (held at one end at least);
            configurationAt(t) returns the configuration at fraction t (its pointers stay valid
            until the next call). @pre both configurations' pointers are set, for all bodies. stop (optional)
           is asked before every round after the first: when it says true the check ends, interrupted
           (SweepCheck::interrupted), so that a planner's time limit reaches into a long check. */
        SweepCheck checkSweep(const Configuration &from, const Configuration &to,
                              const std::function<Configuration(double)> &configurationAt,
                              const std::function<bool()> &stop = {}) const;

        /** Random poses the automatic self-collision check tries (seeded, so every setup finds the
            same pairs). */
        static constexpr unsigned int SELF_CHECK_POSES = 1000;
        /** Share of those poses in which two links must touch to be taken as built to touch. */
        static constexpr double ALWAYS_TOUCHING_SHARE = 0.95;

    private:
        /** Drops from selfPairs_ the pairs that touch in the zero pose and in nearly every random
            pose. */
        void dropAlwaysTouchingPairs();
        /** True when a held object may touch link: the tool link, the links below it and the
            scene's gripper links (RobotSpec::gripperLinks, an SRDF's end effector). */
        bool isGripperLink(int link) const;

        struct Body
        {
            std::unique_ptr<fcl::CollisionObjectd> object;
            Eigen::Isometry3d offset;  ///< shape centre in the body (link or object) frame
            int owner;                 ///< link index or object index
            std::string label;
            bool gripper{false};  ///< robot link at or below the tool link: may touch a held object
            double radius{0.0};   ///< bounding radius of the shape about its centre
            std::optional<ConvexShape>
                convex;  ///< the shape for convexDistance(), unless it is no convex solid
            /** For a mesh taken as its triangles, its convex hull (unless flat): hulls apart prove the
                triangles apart, and the hull's distance bounds the triangles' from below, so most
                queries skip the triangle hierarchy. */
            std::optional<ConvexShape> hull;
        };
        /** What a pair's distance was measured between. */
        enum class Measure
        {
            Boxes,   ///< their bounding boxes (convex)
            Convex,  ///< their convex shapes or a mesh's hull (convex)
            Mesh,    ///< a mesh's triangles (not convex: no secant bound)
            /** an object's distance to the obstacle it rests on at one end of the motion or, where
                larger, its margin of rest on it (Scene::restMargin(); not convex: no secant bound) */
            Rest
        };
        /** A pair's distance and what it measured. */
        struct Measured
        {
            double distance;  ///< a lower bound, DISTANCE_ERROR below it at most; <= 0 when touching
            Measure measure;  ///< what it was measured between
        };
        /** Two bodies that may meet along a motion, and how fast their distance may shrink. */
        struct SweptPair
        {
            const Body *a;
            const Body *b;
            double rate;                          ///< bound on the distance change over the whole motion
            bool translates;                      ///< both only translate (their sweeps have no spread)
            double lastFraction{-1.0};            ///< where the pair's distance was last measured, or -1
            double lastDistance{0.0};             ///< that distance
            Measure lastMeasure{Measure::Boxes};  ///< what lastDistance measured
            bool restsAtAnEnd{false};             ///< object a rests on obstacle b at one end only
            /** Where the pair must be measured again: up to there its last measure keeps it apart */
            double due{0.0};
            /** Up to where its last measure keeps it SAFE_CLEARANCE apart, or -1 */
            double clearUntil{-1.0};
            /** Bound on how fast the bodies' relative speed changes (metres per fraction squared),
                or infinity: only the rate bounds their motion (a carried object) */
            double acceleration{std::numeric_limits<double>::infinity()};
            /** Robot links of a self pair: each moves relative to the other */
            bool self{false};
        };
        /** Bound on the speed at which the bodies of a pair, placed at the motion's current
            fraction, approach each other there (metres per fraction): their velocities
            (MotionBounds::linkVelocity(); a sliding object's is constant) with their turns times
            their reach. */
        double approachSpeed(const SweptPair &pair, const double *q1, const double *q2) const;
        /** How far along the motion (fraction) a pair stays closer than `margin` less than now:
            by the rate, or by its speed now and its acceleration, whichever reaches farther. */
        static double stepWithin(const SweptPair &pair, double margin, double closing, double speed);
        /** The distance of the bodies of a pair, placed: of their convex shapes; of a mesh's hull
            while that is at least HULL_TRUSTED away; else of the triangles. For an object that
            rests on the obstacle at one end (SweptPair::restsAtAnEnd), whichever is larger of that
            and its rest margin on the obstacle's surfaces (Scene::restMargin()): where it rests it
            may touch. */
        Measured distance(const SweptPair &pair) const;
        /** The distance of two placed bodies' shapes, as distance() measures a pair. */
        static Measured shapeDistance(const Body &a, const Body &b);
        /** True when two placed bodies overlap: their boxes, then their hulls, then their shapes. */
        static bool bodiesCollide(const Body &a, const Body &b);
        /** A hull distance from which on a mesh pair is measured by the hulls, metres: below it the
            triangles decide, so contacts and near misses are the triangles' own. */
        static constexpr double HULL_TRUSTED = 2.0 * SAFE_CLEARANCE;
        /** What measuring a pair along a motion found. */
        enum class Progress
        {
            Apart,     ///< the pair cannot meet for the rest of the motion
            Touching,  ///< closer than MIN_CLEARANCE: the motion is blocked
            Due        ///< apart: SweptPair::due tells where to measure it again
        };
        /** Measures a pair placed at fraction t of a motion (conservative advancement): whether it
            touches, cannot meet any more, or else up to where it stays apart (its due, keeping
            SAFE_CLEARANCE short of a contact ahead, or half of MIN_CLEARANCE when closer) and
            SAFE_CLEARANCE apart (its clearUntil). */
        Progress advance(SweptPair &pair, double t, const double *q1, const double *q2) const;
        /** The object index of a body, or -1 for a robot link or an obstacle. */
        int objectOf(const Body *body) const;
        /** The robot link index of a body, or -1 for an object or an obstacle. */
        int linkOf(const Body *body) const;
        /** The reach of a body's points from its owner's origin, metres. */
        static double reach(const Body &body) { return body.offset.translation().norm() + body.radius; }
        /** The object of a pair in contact that SweepCheck::blockingObject names, or -1. */
        int blockingObject(const SweptPair &pair) const;

        /** Fills sweptPairs_ with the pairs a motion may bring together. */
        void findSweptPairs(const Configuration &from, const Configuration &to) const;

        void placeBodies(const Configuration &configuration) const;
        bool hitsObstacle(const Body &body, int allowedObstacle, std::string *contact) const;
        bool robotFree(const Configuration &configuration, std::string *contact) const;
        bool objectsFree(const Configuration &configuration, std::string *contact) const;
        static bool isPresent(const Configuration &configuration, int object)
        {
            return !configuration.present || (*configuration.present)[object];
        }
        static bool isHeld(const Configuration &configuration, int object)
        {
            return (*configuration.restingSurfaces)[object] < 0;
        }
        /** True when the object rests on a surface of the obstacle. */
        bool restsOn(const Configuration &configuration, int object, int obstacle) const
        {
            const int surface = (*configuration.restingSurfaces)[object];
            return surface >= 0 && surfaceObstacle_[surface] == obstacle;
        }

        ManipulationModelPtr model_;
        std::vector<Body> robotBodies_;
        std::vector<Body> objectBodies_;
        std::vector<Body> obstacleBodies_;
        std::vector<std::pair<std::size_t, std::size_t>> selfPairs_;  ///< robot body pairs to check
        std::vector<int> surfaceObstacle_;  ///< per surface, the obstacle it belongs to, or -1
        std::unique_ptr<fcl::BroadPhaseCollisionManagerd> obstacleTree_;
        mutable std::vector<Eigen::Isometry3d> linkFrames_;
        MotionBounds bounds_;
        // buffers of checkSweep, kept to spare allocations in planners' inner loops
        mutable std::vector<BodySweep> robotSweeps_;
        mutable std::vector<BodySweep> objectSweeps_;
        mutable std::vector<SweptPair> sweptPairs_;
        mutable std::vector<MotionBounds::CarriedGrasp> carriedGrasps_;
        mutable std::vector<double> robotAccelerations_;
        mutable std::vector<double> objectAccelerations_;
    };
}  // namespace ompl_mm
