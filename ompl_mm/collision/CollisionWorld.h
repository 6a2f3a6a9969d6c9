#pragma once

#include "ompl_mm/model/ManipulationModel.h"

#include <fcl/fcl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ompl_mm
{
    /** Makes the FCL geometry of a shape (cylinders along z, centred); the caller shares its
        ownership. @throws ompl::Exception for a shape kind outside Shape::Kind. */
    std::shared_ptr<fcl::CollisionGeometryd> makeCollisionGeometry(const Shape &shape);

    /** Collision checking of one manipulation configuration with FCL: robot links, movable
        objects and the fixed obstacles (in a broad-phase tree). It applies the contact rules of the
        state-based validity: a held object may touch the gripper (the tool link and the links below
        it), a resting object may touch the obstacle its surface belongs to, listed robot link pairs
        are ignored, and adjacent links never collide with each other. Not thread-safe: queries move
        the bodies. Not copyable (FCL objects hold raw pointers). */
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
            collision pair names an unknown link. */
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

    private:
        struct Body
        {
            std::unique_ptr<fcl::CollisionObjectd> object;
            Eigen::Isometry3d offset;  ///< shape centre in the body (link or object) frame
            int owner;                 ///< link index or object index
            std::string label;
            bool gripper{false};  ///< robot link at or below the tool link: may touch a held object
        };

        void placeBodies(const Configuration &configuration) const;
        bool hitsObstacle(const Body &body, int allowedObstacle, std::string *contact) const;
        bool robotFree(const Configuration &configuration, std::string *contact) const;
        bool objectsFree(const Configuration &configuration, std::string *contact) const;
        static bool isPresent(const Configuration &configuration, int object)
        {
            return !configuration.present || (*configuration.present)[object];
        }

        ManipulationModelPtr model_;
        std::vector<Body> robotBodies_;
        std::vector<Body> objectBodies_;
        std::vector<Body> obstacleBodies_;
        std::vector<std::pair<std::size_t, std::size_t>> selfPairs_;  ///< robot body pairs to check
        std::vector<int> surfaceObstacle_;  ///< per surface, the obstacle it belongs to, or -1
        std::unique_ptr<fcl::BroadPhaseCollisionManagerd> obstacleTree_;
        mutable std::vector<Eigen::Isometry3d> linkFrames_;
    };
}  // namespace ompl_mm
