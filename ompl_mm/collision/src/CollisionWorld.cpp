#include "ompl_mm/collision/CollisionWorld.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "ompl_core/io/InputError.h"
#include "ompl_mm/collision/ConvexDistance.h"
#include "ompl_mm/scene/ConvexHull.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace ompl_mm
{
    namespace
    {
        bool narrowPhase(const fcl::CollisionObjectd &a, const fcl::CollisionObjectd &b)
        {
            fcl::CollisionRequestd request;
            fcl::CollisionResultd result;
            return fcl::collide(&a, &b, request, result) > 0;
        }

        void place(fcl::CollisionObjectd &object, const Eigen::Isometry3d &frame)
        {
            object.setTransform(frame.linear(), frame.translation());
            object.computeAABB();
        }

        /** FCL's convex polytope of a hull: its corners, and its triangles as FCL's face list
            (3, i0, i1, i2, 3, ...), outward as FCL wants them. */
        std::shared_ptr<fcl::Convexd> convexPolytope(const ConvexHull &hull)
        {
            auto vertices = std::make_shared<std::vector<fcl::Vector3d>>(hull.vertices);
            auto faces = std::make_shared<std::vector<int>>();
            faces->reserve(4 * hull.triangles.size());
            for (const std::array<int, 3> &t : hull.triangles)
                faces->insert(faces->end(), {3, t[0], t[1], t[2]});
            // throw_if_invalid: FCL checks the topology (every edge shared by two faces)
            auto convex = std::make_shared<fcl::Convexd>(vertices, static_cast<int>(hull.triangles.size()),
                                                         faces, true);
            convex->computeLocalAABB();
            return convex;
        }
    }  // namespace

    std::shared_ptr<fcl::CollisionGeometryd> makeCollisionGeometry(const Shape &shape, MeshCollision meshes)
    {
        switch (shape.kind)
        {
            case Shape::Kind::Box:
                return std::make_shared<fcl::Boxd>(shape.boxSize.x(), shape.boxSize.y(), shape.boxSize.z());
            case Shape::Kind::Cylinder:
                return std::make_shared<fcl::Cylinderd>(shape.radius, shape.length);
            case Shape::Kind::Sphere:
                return std::make_shared<fcl::Sphered>(shape.radius);
            case Shape::Kind::Mesh:
            {
                if (meshes == MeshCollision::ConvexHull)
                    return convexPolytope(*shape.mesh->convexHull());
                auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
                std::vector<fcl::Triangle> triangles;
                for (const std::array<int, 3> &t : shape.mesh->triangles)
                    triangles.emplace_back(t[0], t[1], t[2]);
                model->beginModel();
                model->addSubModel(shape.mesh->vertices, triangles);
                model->endModel();
                model->computeLocalAABB();
                return model;
            }
        }
        throw ompl::Exception("unknown shape kind");
    }

    CollisionWorld::CollisionWorld(ManipulationModelPtr model) : model_(std::move(model)), bounds_(model_)
    {
        const Scene &scene = model_->scene();
        const RobotModel &robot = model_->robot();
        for (std::size_t l = 0; l < robot.links().size(); ++l)
            for (const LinkShape &s : robot.links()[l].shapes)
            {
                const std::string label = "robot link '" + robot.links()[l].name + "'";
                std::shared_ptr<fcl::CollisionGeometryd> geometry;
                try
                {
                    geometry = makeCollisionGeometry(s.shape, scene.robot.meshCollision);
                }
                catch (const ompl::Exception &e)
                {
                    // only a hull fails here: name the link, and the scene line that asked for hulls
                    throw ompl_core::InputError(
                        scene.robot.where,
                        label + ": " + e.what() + " (meshes=\"exact\" takes its triangles)");
                }
                robotBodies_.push_back({std::make_unique<fcl::CollisionObjectd>(geometry), s.origin,
                                        static_cast<int>(l), label, isGripperLink(static_cast<int>(l)),
                                        s.shape.boundingRadius(),
                                        ConvexShape::of(s.shape, scene.robot.meshCollision), std::nullopt});
                if (!robotBodies_.back().convex && s.shape.kind == Shape::Kind::Mesh)
                    try
                    {
                        robotBodies_.back().hull = ConvexShape::of(s.shape, MeshCollision::ConvexHull);
                    }
                    catch (const ompl::Exception &)
                    {
                        // a flat mesh has no hull: its triangles answer every query
                    }
            }

        for (std::size_t i = 0; i < scene.objects.size(); ++i)
        {
            const Shape &shape = scene.objects[i].shape;
            Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
            offset.translation().z() = 0.5 * shape.height();  // the object frame is at its base
            objectBodies_.push_back({std::make_unique<fcl::CollisionObjectd>(makeCollisionGeometry(shape)),
                                     offset, static_cast<int>(i), "object '" + scene.objects[i].name + "'",
                                     false, shape.boundingRadius(),
                                     ConvexShape::of(shape, MeshCollision::Exact), std::nullopt});
        }

        obstacleTree_ = std::make_unique<fcl::DynamicAABBTreeCollisionManagerd>();
        for (std::size_t i = 0; i < scene.obstacles.size(); ++i)
        {
            Body body{
                std::make_unique<fcl::CollisionObjectd>(makeCollisionGeometry(scene.obstacles[i].shape)),
                Eigen::Isometry3d::Identity(),
                static_cast<int>(i),
                "obstacle '" + scene.obstacles[i].name + "'",
                false,
                scene.obstacles[i].shape.boundingRadius(),
                ConvexShape::of(scene.obstacles[i].shape, MeshCollision::Exact),
                std::nullopt};
            place(*body.object, scene.obstacles[i].pose);
            body.object->setUserData(reinterpret_cast<void *>(i + 1));  // the obstacle's index + 1
            obstacleTree_->registerObject(body.object.get());
            obstacleBodies_.push_back(std::move(body));
        }
        obstacleTree_->setup();

        for (const SupportSurface &s : scene.surfaces)
        {
            int index = -1;
            for (std::size_t i = 0; i < scene.obstacles.size(); ++i)
                if (scene.obstacles[i].name == s.obstacle)
                    index = static_cast<int>(i);
            if (!s.obstacle.empty() && index < 0)
                throw ompl_core::InputError(
                    s.where, "surface '" + s.name + "' names unknown obstacle '" + s.obstacle + "'");
            surfaceObstacle_.push_back(index);
        }

        // self-collision: links that are neither adjacent nor listed as allowed
        std::vector<std::pair<int, int>> allowed;
        const auto linkOf = [&robot](const AllowedCollision &pair, const std::string &name)
        {
            const int index = robot.findLink(name);
            if (index < 0)
                throw ompl_core::InputError(pair.where, "allow_collision names link '" + name +
                                                            "', which robot '" + robot.name() +
                                                            "' does not have");
            return index;
        };
        for (const AllowedCollision &pair : scene.robot.allowedCollisions)
            allowed.emplace_back(linkOf(pair, pair.link1), linkOf(pair, pair.link2));
        for (std::size_t a = 0; a < robotBodies_.size(); ++a)
            for (std::size_t b = a + 1; b < robotBodies_.size(); ++b)
            {
                const int la = robotBodies_[a].owner, lb = robotBodies_[b].owner;
                const bool adjacent =
                    la == lb || robot.links()[la].parent == lb || robot.links()[lb].parent == la;
                const bool listed =
                    std::find(allowed.begin(), allowed.end(), std::make_pair(la, lb)) != allowed.end() ||
                    std::find(allowed.begin(), allowed.end(), std::make_pair(lb, la)) != allowed.end();
                if (!adjacent && !listed)
                    selfPairs_.emplace_back(a, b);
            }
        linkFrames_.resize(robot.links().size());
        dropAlwaysTouchingPairs();
    }

    bool CollisionWorld::isGripperLink(int link) const
    {
        const RobotModel &robot = model_->robot();
        const std::vector<std::string> &listed = model_->scene().robot.gripperLinks;
        return robot.isInSubtree(link, model_->toolLink()) ||
               std::find(listed.begin(), listed.end(), robot.links()[link].name) != listed.end();
    }

    void CollisionWorld::dropAlwaysTouchingPairs()
    {
        if (selfPairs_.empty())
            return;
        const RobotModel &robot = model_->robot();
        const Eigen::Isometry3d &base = model_->scene().robot.basePose;
        const auto touchingPairs = [&](const std::vector<double> &q)
        {
            robot.forwardKinematics(q.data(), base, linkFrames_);
            for (const Body &body : robotBodies_)
                place(*body.object, linkFrames_[body.owner] * body.offset);
            std::vector<bool> touching(selfPairs_.size());
            for (std::size_t p = 0; p < selfPairs_.size(); ++p)
                touching[p] =
                    bodiesCollide(robotBodies_[selfPairs_[p].first], robotBodies_[selfPairs_[p].second]);
            return touching;
        };
        const std::vector<bool> atZero = touchingPairs(std::vector<double>(robot.dof(), 0.0));
        std::vector<unsigned int> counts(selfPairs_.size(), 0);
        ompl::RNG rng(1);  // a fixed seed: the same pairs for every setup of a scene
        std::vector<double> q(robot.dof());
        for (unsigned int k = 0; k < SELF_CHECK_POSES; ++k)
        {
            for (unsigned int i = 0; i < robot.dof(); ++i)
                q[i] = rng.uniformReal(robot.variableJoint(i).lower, robot.variableJoint(i).upper);
            const std::vector<bool> touching = touchingPairs(q);
            for (std::size_t p = 0; p < selfPairs_.size(); ++p)
                counts[p] += touching[p] ? 1 : 0;
        }
        std::vector<std::pair<std::size_t, std::size_t>> kept;
        for (std::size_t p = 0; p < selfPairs_.size(); ++p)
        {
            if (atZero[p] && counts[p] >= ALWAYS_TOUCHING_SHARE * SELF_CHECK_POSES)
                OMPL_INFORM("%s and %s touch in the zero pose and in %u of %u random poses: never checked",
                            robotBodies_[selfPairs_[p].first].label.c_str(),
                            robotBodies_[selfPairs_[p].second].label.c_str(), counts[p], SELF_CHECK_POSES);
            else
                kept.push_back(selfPairs_[p]);
        }
        selfPairs_ = std::move(kept);
    }

    CollisionWorld::~CollisionWorld() = default;

    CollisionWorld::Measured CollisionWorld::distance(const SweptPair &pair) const
    {
        const Measured shapes = shapeDistance(*pair.a, *pair.b);
        if (!pair.restsAtAnEnd)
            return shapes;
        const Eigen::Isometry3d &frame = pair.a->object->getTransform();
        const Eigen::Vector3d base = frame.translation() - frame.linear() * pair.a->offset.translation();
        const double rests = model_->scene().restMargin(
            base, [&](int surface) { return surfaceObstacle_[surface] == pair.b->owner; });
        return {std::max(shapes.distance, rests), Measure::Rest};
    }

    CollisionWorld::Measured CollisionWorld::shapeDistance(const Body &a, const Body &b)
    {
        // convex solids by our GJK, whose lower bound is what conservative advancement needs
        if (a.convex && b.convex)
            return {convexDistance(*a.convex, a.object->getTransform(), *b.convex, b.object->getTransform(),
                                   DISTANCE_ERROR),
                    Measure::Convex};
        // a mesh by its hull while that is far: the hull holds the mesh, so its distance is a lower
        // bound of the triangles'
        const std::optional<ConvexShape> &boundA = a.convex ? a.convex : a.hull;
        const std::optional<ConvexShape> &boundB = b.convex ? b.convex : b.hull;
        if (boundA && boundB)
        {
            const double hulls = convexDistance(*boundA, a.object->getTransform(), *boundB,
                                                b.object->getTransform(), DISTANCE_ERROR);
            if (hulls >= HULL_TRUSTED)
                return {hulls, Measure::Convex};
        }
        fcl::DistanceRequestd request;
        fcl::DistanceResultd result;
        fcl::distance(a.object.get(), b.object.get(), request, result);
        return {result.min_distance, Measure::Mesh};
    }

    bool CollisionWorld::bodiesCollide(const Body &a, const Body &b)
    {
        if (!a.object->getAABB().overlap(b.object->getAABB()))
            return false;
        // hulls apart: the meshes they hold are apart
        const std::optional<ConvexShape> &boundA = a.convex ? a.convex : a.hull;
        const std::optional<ConvexShape> &boundB = b.convex ? b.convex : b.hull;
        if ((a.hull || b.hull) && boundA && boundB &&
            convexDistance(*boundA, a.object->getTransform(), *boundB, b.object->getTransform(),
                           DISTANCE_ERROR) > 0.0)
            return false;
        return narrowPhase(*a.object, *b.object);
    }

    void CollisionWorld::placeBodies(const Configuration &configuration) const
    {
        if (configuration.joints)
        {
            model_->robot().forwardKinematics(configuration.joints, model_->scene().robot.basePose,
                                              linkFrames_);
            for (const Body &body : robotBodies_)
                place(*body.object, linkFrames_[body.owner] * body.offset);
        }
        for (const Body &body : objectBodies_)
            if (isPresent(configuration, body.owner))
                place(*body.object, (*configuration.objects)[body.owner].frame() * body.offset);
    }

    bool CollisionWorld::hitsObstacle(const Body &body, int allowedObstacle, std::string *contact) const
    {
        struct Query
        {
            const CollisionWorld *world;
            const Body *body;
            int allowed;
            int hit{-1};
        } query{this, &body, allowedObstacle};
        const auto callback = [](fcl::CollisionObjectd *o1, fcl::CollisionObjectd *o2, void *data)
        {
            auto *q = static_cast<Query *>(data);
            // the manager passes the query body and a tree body in either order; tree bodies carry
            // their index + 1
            const auto index =
                reinterpret_cast<std::uintptr_t>(o1->getUserData() ? o1->getUserData() : o2->getUserData());
            const int obstacle = static_cast<int>(index) - 1;
            if (obstacle == q->allowed || !bodiesCollide(*q->body, q->world->obstacleBodies_[obstacle]))
                return false;
            q->hit = obstacle;
            return true;
        };
        obstacleTree_->collide(body.object.get(), &query, callback);
        if (query.hit < 0)
            return false;
        if (contact)
            *contact = body.label + " and " + obstacleBodies_[query.hit].label;
        return true;
    }

    bool CollisionWorld::robotFree(const Configuration &configuration, std::string *contact) const
    {
        for (const Body &link : robotBodies_)
        {
            if (hitsObstacle(link, -1, contact))
                return false;
            for (const Body &object : objectBodies_)
            {
                if (!isPresent(configuration, object.owner) ||
                    (link.gripper && (*configuration.restingSurfaces)[object.owner] < 0))
                    continue;
                if (bodiesCollide(link, object))
                {
                    if (contact)
                        *contact = link.label + " and " + object.label;
                    return false;
                }
            }
        }
        for (const auto &[a, b] : selfPairs_)
            if (bodiesCollide(robotBodies_[a], robotBodies_[b]))
            {
                if (contact)
                    *contact = robotBodies_[a].label + " and " + robotBodies_[b].label;
                return false;
            }
        return true;
    }

    bool CollisionWorld::objectsFree(const Configuration &configuration, std::string *contact) const
    {
        for (std::size_t i = 0; i < objectBodies_.size(); ++i)
        {
            if (!isPresent(configuration, static_cast<int>(i)))
                continue;
            const int surface = (*configuration.restingSurfaces)[i];
            if (hitsObstacle(objectBodies_[i], surface >= 0 ? surfaceObstacle_[surface] : -1, contact))
                return false;
            for (std::size_t j = i + 1; j < objectBodies_.size(); ++j)
                if (isPresent(configuration, static_cast<int>(j)) &&
                    bodiesCollide(objectBodies_[i], objectBodies_[j]))
                {
                    if (contact)
                        *contact = objectBodies_[i].label + " and " + objectBodies_[j].label;
                    return false;
                }
        }
        return true;
    }

    bool CollisionWorld::isCollisionFree(const Configuration &configuration, std::string *contact) const
    {
        placeBodies(configuration);
        return objectsFree(configuration, contact) &&
               (!configuration.joints || robotFree(configuration, contact));
    }

    void CollisionWorld::findSweptPairs(const Configuration &from, const Configuration &to) const
    {
        std::vector<BodySweep> &robotSweeps = robotSweeps_;
        robotSweeps.clear();
        for (const Body &link : robotBodies_)
            robotSweeps.push_back(bounds_.linkSweep(
                link.owner, link.offset.translation().norm() + link.radius, from.joints, to.joints));
        std::vector<BodySweep> &objectSweeps = objectSweeps_;
        objectSweeps.clear();
        std::vector<MotionBounds::CarriedGrasp> &grasps = carriedGrasps_;
        grasps.assign(objectBodies_.size(), {});
        for (const Body &object : objectBodies_)
        {
            const ObjectPose &a = (*from.objects)[object.owner];
            const ObjectPose &b = (*to.objects)[object.owner];
            if (isHeld(from, object.owner) || isHeld(to, object.owner))
            {
                grasps[object.owner] = bounds_.carriedGrasp(a, b, reach(object), from.joints, to.joints);
                objectSweeps.push_back(bounds_.carriedSweep(grasps[object.owner], from.joints, to.joints));
            }
            else
                objectSweeps.push_back(MotionBounds::slideSweep(a, b, object.radius));
        }
        // how fast each body's points may change their speed: a link's by its joints, a sliding
        // object's by its turn; a carried object's is not bounded here (its rate alone bounds it)
        std::vector<double> &robotAccelerations = robotAccelerations_;
        robotAccelerations.clear();
        for (const Body &link : robotBodies_)
            robotAccelerations.push_back(
                from.joints ? bounds_.linkAcceleration(link.owner, reach(link), from.joints, to.joints)
                            : 0.0);
        std::vector<double> &objectAccelerations = objectAccelerations_;
        objectAccelerations.clear();
        for (const Body &object : objectBodies_)
        {
            const BodySweep &sweep = objectSweeps[object.owner];
            const bool carried = isHeld(from, object.owner) || isHeld(to, object.owner);
            objectAccelerations.push_back(carried             ? std::numeric_limits<double>::infinity()
                                          : object.radius > 0 ? sweep.spread * sweep.spread / object.radius
                                                              : 0.0);
        }
        const BodySweep still;
        std::vector<SweptPair> &pairs = sweptPairs_;
        pairs.clear();
        // true when the pair was added
        const auto add = [&pairs](const Body &a, const Body &b, const BodySweep &sa, const BodySweep &sb,
                                  double acceleration)
        {
            const double rate = (sa.translation - sb.translation).norm() + sa.spread + sb.spread;
            if (rate <= 0.0)  // bodies that keep their distance keep what both ends' checks found
                return false;
            pairs.push_back({&a, &b, rate, sa.spread == 0.0 && sb.spread == 0.0});
            pairs.back().acceleration = acceleration;
            return true;
        };
        for (std::size_t l = 0; l < robotBodies_.size(); ++l)
        {
            for (const Body &obstacle : obstacleBodies_)
                add(robotBodies_[l], obstacle, robotSweeps[l], still, robotAccelerations[l]);
            for (const Body &object : objectBodies_)
            {
                const Body &link = robotBodies_[l];
                const bool carried = isHeld(from, object.owner) || isHeld(to, object.owner);
                if (carried && link.gripper)
                    continue;
                // an upright body, the same after any turn about its vertical axis, carried with the
                // tool: only the joints between the link and the tool and the grasp's shift move it
                // relative to the link, and the joints above both by tilting it
                const bool symmetric = model_->scene().objects[object.owner].shape.turnsFreely() &&
                                       object.offset.translation().head<2>().isZero();
                if (carried && symmetric)
                {
                    const double rate = bounds_.carriedRelativeRate(
                        link.owner, reach(link), grasps[object.owner], reach(object), from.joints, to.joints);
                    if (rate > 0.0)
                        pairs.push_back({&link, &object, rate, false});
                }
                else
                    add(link, object, robotSweeps[l], objectSweeps[object.owner],
                        robotAccelerations[l] + objectAccelerations[object.owner]);
            }
        }
        // links measured against each other: only the joints between them count
        for (const auto &[a, b] : selfPairs_)
        {
            const Body &la = robotBodies_[a];
            const Body &lb = robotBodies_[b];
            const double rate =
                bounds_.relativeRate(la.owner, la.offset.translation().norm() + la.radius, lb.owner,
                                     lb.offset.translation().norm() + lb.radius, from.joints, to.joints);
            if (rate > 0.0)
            {
                pairs.push_back({&la, &lb, rate, false});
                pairs.back().acceleration =
                    bounds_.linkAcceleration(la.owner, reach(la), from.joints, to.joints, lb.owner) +
                    bounds_.linkAcceleration(lb.owner, reach(lb), from.joints, to.joints, la.owner);
                pairs.back().self = true;
            }
        }
        for (std::size_t i = 0; i < objectBodies_.size(); ++i)
        {
            for (const Body &obstacle : obstacleBodies_)
            {
                // an object that rests on the obstacle at both ends slides on its (planar, convex)
                // surface; one put down on it or lifted off it may touch it where it rests
                const bool restsFrom = restsOn(from, static_cast<int>(i), obstacle.owner);
                const bool restsTo = restsOn(to, static_cast<int>(i), obstacle.owner);
                if (restsFrom && restsTo)
                    continue;
                if (add(objectBodies_[i], obstacle, objectSweeps[i], still, objectAccelerations[i]))
                    pairs.back().restsAtAnEnd = restsFrom != restsTo;
            }
            for (std::size_t j = i + 1; j < objectSweeps.size(); ++j)
                add(objectBodies_[i], objectBodies_[j], objectSweeps[i], objectSweeps[j],
                    objectAccelerations[i] + objectAccelerations[j]);
        }
    }

    double CollisionWorld::approachSpeed(const SweptPair &pair, const double *q1, const double *q2) const
    {
        Eigen::Vector3d linear = Eigen::Vector3d::Zero();
        double turning = 0.0;
        const auto add = [&](const Body *body, const Body *other, double sign)
        {
            const int link = linkOf(body);
            const int object = objectOf(body);
            if (link >= 0)
            {
                const BodyVelocity velocity =
                    bounds_.linkVelocity(link, linkFrames_, q1, q2, pair.self ? other->owner : -1);
                linear += sign * velocity.linear;
                turning += velocity.angular.norm() * reach(*body);
            }
            else if (object >= 0)
            {
                linear += sign * objectSweeps_[static_cast<std::size_t>(object)].translation;
                turning += objectSweeps_[static_cast<std::size_t>(object)].spread;
            }
        };
        add(pair.a, pair.b, 1.0);
        add(pair.b, pair.a, -1.0);
        return linear.norm() + turning;
    }

    double CollisionWorld::stepWithin(const SweptPair &pair, double margin, double closing, double speed)
    {
        const double byRate = margin / closing;
        if (!std::isfinite(pair.acceleration))
            return byRate;
        // speed * h + acceleration * h^2 / 2 = margin, solved without cancellation
        const double bySpeed =
            2.0 * margin / (speed + std::sqrt(speed * speed + 2.0 * pair.acceleration * margin));
        return std::max(byRate, bySpeed);
    }

    CollisionWorld::Progress CollisionWorld::advance(SweptPair &pair, double t, const double *q1,
                                                     const double *q2) const
    {
        const double remaining = (1.0 - t) * pair.rate;
        // bounding boxes first: their gap is a lower bound on the distance; a pair that cannot come
        // near for the rest of the way is done
        const double apart = pair.a->object->getAABB().distance(pair.b->object->getAABB());
        if (apart > remaining + SAFE_CLEARANCE)
        {
            pair.clearUntil = std::numeric_limits<double>::infinity();
            return Progress::Apart;
        }
        const bool exact = apart <= 2.0 * SAFE_CLEARANCE;
        const Measured measured = exact ? distance(pair) : Measured{apart, Measure::Boxes};
        const double d = measured.distance;
        if (d < MIN_CLEARANCE)
            return Progress::Touching;
        pair.clearUntil = d >= SAFE_CLEARANCE ? t : -1.0;
        // stop a safe clearance short of a contact ahead, then close in as far as keeps half the
        // least clearance (so any part of a motion it accepts passes too)
        const double keep = d > 2.0 * SAFE_CLEARANCE ? SAFE_CLEARANCE : 0.5 * MIN_CLEARANCE;
        // convex bodies in relative translation: the distance (of the shapes, or of their boxes) is
        // convex along the motion, so the line through its last two measures, allowing for their
        // error, bounds it from below from here on
        double closing = pair.rate;
        const bool convex = measured.measure == Measure::Boxes || measured.measure == Measure::Convex;
        if (pair.translates && pair.lastFraction >= 0.0 && pair.lastMeasure == measured.measure && convex)
            closing =
                std::min(closing, (pair.lastDistance - d + 2.0 * DISTANCE_ERROR) / (t - pair.lastFraction));
        if (closing <= 0.0)
            return Progress::Apart;  // only moving apart from here
        // the pair's speed now and how fast it may change, where that bounds it closer than the rate
        const double speed = std::isfinite(pair.acceleration) ? approachSpeed(pair, q1, q2) : closing;
        pair.due = t + stepWithin(pair, d - DISTANCE_ERROR - keep, closing, speed);
        if (d >= SAFE_CLEARANCE)
            pair.clearUntil =
                t + stepWithin(pair, std::max(0.0, d - DISTANCE_ERROR - SAFE_CLEARANCE), closing, speed);
        pair.lastFraction = t;
        pair.lastDistance = d;
        pair.lastMeasure = measured.measure;
        return Progress::Due;
    }

    CollisionWorld::SweepCheck CollisionWorld::checkSweep(
        const Configuration &from, const Configuration &to,
        const std::function<Configuration(double)> &configurationAt, const std::function<bool()> &stop) const
    {
        findSweptPairs(from, to);
        std::vector<SweptPair> &pairs = sweptPairs_;
        double t = 0.0;
        double safe = 0.0;
        placeBodies(from);
        for (unsigned int round = 0; round < MAX_SWEEP_ROUNDS; ++round)
        {
            // the pairs due here first; then those whose last measure would end the next step
            // before the fresh measures do, so that a step is never shorter than with every pair
            // measured, and a pair far from contact is measured only every few steps
            double next = std::numeric_limits<double>::infinity();
            bool clear = true;  // every pair a safe clearance apart here
            for (const bool due : {true, false})
                for (std::size_t k = 0; k < pairs.size();)
                {
                    SweptPair &pair = pairs[k];
                    if (due ? pair.due > t : pair.due >= next)
                    {
                        ++k;
                        continue;
                    }
                    const Progress progress = advance(pair, t, from.joints, to.joints);
                    if (progress == Progress::Touching)
                        return {false, safe, blockingObject(pair), {pair.a->label, pair.b->label}};
                    if (progress == Progress::Apart)
                    {
                        clear = clear && t <= pair.clearUntil;
                        pairs[k] = pairs.back();
                        pairs.pop_back();
                        continue;
                    }
                    next = std::min(next, pair.due);
                    ++k;
                }
            // up to where every pair stays a safe clearance apart, within what is shown free
            double clearTo = std::numeric_limits<double>::infinity();
            for (const SweptPair &pair : pairs)
            {
                next = std::min(next, pair.due);
                clear = clear && pair.clearUntil >= t;
                clearTo = std::min(clearTo, pair.clearUntil);
            }
            if (clear)
                safe = std::min(next, clearTo);
            if (pairs.empty() || next >= 1.0)
                return {true, 1.0};
            if (stop && stop())
                return {false, safe, -1, {}, true};
            t = next;
            placeBodies(configurationAt(t));
        }
        return {false, safe};
    }

    int CollisionWorld::objectOf(const Body *body) const
    {
        const bool isObject =
            body >= objectBodies_.data() && body < objectBodies_.data() + objectBodies_.size();
        return isObject ? body->owner : -1;
    }

    int CollisionWorld::linkOf(const Body *body) const
    {
        const bool isLink = body >= robotBodies_.data() && body < robotBodies_.data() + robotBodies_.size();
        return isLink ? body->owner : -1;
    }

    int CollisionWorld::blockingObject(const SweptPair &pair) const
    {
        const int a = objectOf(pair.a);
        const int b = objectOf(pair.b);
        if (a < 0 || b < 0)
            return std::max(a, b);
        // two objects: the one in the way is the one that moves less
        const auto travel = [this](int object)
        {
            const BodySweep &sweep = objectSweeps_[static_cast<std::size_t>(object)];
            return sweep.translation.norm() + sweep.spread;
        };
        return travel(a) < travel(b) ? a : b;
    }

    std::string CollisionWorld::contactAmong(const double *joints,
                                             const std::vector<std::optional<ObjectPose>> &objects) const
    {
        std::vector<ObjectPose> poses(objects.size());
        std::vector<int> resting(objects.size(), -1);
        std::vector<char> present(objects.size(), 0);
        for (std::size_t i = 0; i < objects.size(); ++i)
            if (objects[i])
            {
                poses[i] = *objects[i];
                resting[i] = model_->scene().restingSurface(poses[i].position);
                present[i] = 1;
            }
        std::string contact;
        isCollisionFree({joints, &poses, &resting, &present}, &contact);
        return contact;
    }
}  // namespace ompl_mm
