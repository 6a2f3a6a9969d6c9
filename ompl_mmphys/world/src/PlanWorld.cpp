#include "ompl_mmphys/world/PlanWorld.h"

#include "ompl_phys/world/OdeGeometry.h"

#include <ode/ode.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>

namespace ompl_mmphys
{
    /** A triangle mesh as ODE reads it, kept while its geom lives (PlanWorld's own type). */
    struct OdeMesh
    {
        std::vector<dReal> vertices;  ///< x y z per vertex
        std::vector<dTriIndex> indices;
        dTriMeshDataID data{nullptr};
    };

    namespace
    {
        /** Thickness of the slab under a support surface that is no obstacle's top, metres. */
        constexpr double SLAB_THICKNESS = 0.1;
        /** Most contact points dCollide may return for one pair. */
        constexpr int MAX_CONTACT_POINTS = 16;
        /** Seed of ODE's generator (QuickStep's order of constraints) for every world. */
        constexpr unsigned long ODE_SEED = 1;
        /** Contacts are created this far before geometry touches; damps resting jitter, metres. */
        constexpr double SURFACE_LAYER = 0.001;
        /** How far below the lowest support surface or obstacle an object that fell out of the world
            is stopped, metres: it would fall on for ever. */
        constexpr double FALL_DEPTH = 1.0;

        dGeomID createGeom(dSpaceID space, const ompl_mm::Shape &shape, std::deque<OdeMesh> &meshes)
        {
            using Kind = ompl_mm::Shape::Kind;
            switch (shape.kind)
            {
                case Kind::Box:
                    return dCreateBox(space, shape.boxSize.x(), shape.boxSize.y(), shape.boxSize.z());
                case Kind::Cylinder:
                    return dCreateCylinder(space, shape.radius, shape.length);
                case Kind::Sphere:
                    return dCreateSphere(space, shape.radius);
                case Kind::Mesh:
                    break;
            }
            OdeMesh &mesh = meshes.emplace_back();
            for (const Eigen::Vector3d &v : shape.mesh->vertices)
                mesh.vertices.insert(mesh.vertices.end(), {v.x(), v.y(), v.z()});
            for (const std::array<int, 3> &t : shape.mesh->triangles)
                mesh.indices.insert(mesh.indices.end(),
                                    {static_cast<dTriIndex>(t[0]), static_cast<dTriIndex>(t[1]),
                                     static_cast<dTriIndex>(t[2])});
            mesh.data = dGeomTriMeshDataCreate();
            dGeomTriMeshDataBuildDouble(mesh.data, mesh.vertices.data(), 3 * sizeof(dReal),
                                        static_cast<int>(shape.mesh->vertices.size()), mesh.indices.data(),
                                        static_cast<int>(mesh.indices.size()), 3 * sizeof(dTriIndex));
            return dCreateTriMesh(space, mesh.data, nullptr, nullptr, nullptr);
        }

        void setMass(dBodyID body, const ompl_mm::Shape &shape, double mass)
        {
            dMass m;
            using Kind = ompl_mm::Shape::Kind;
            if (shape.kind == Kind::Box)
                dMassSetBoxTotal(&m, mass, shape.boxSize.x(), shape.boxSize.y(), shape.boxSize.z());
            else if (shape.kind == Kind::Cylinder)
                dMassSetCylinderTotal(&m, mass, 3, shape.radius, shape.length);  // 3: along z
            else
                dMassSetSphereTotal(&m, mass, shape.boundingRadius());
            dBodySetMass(body, &m);
        }

        Eigen::Isometry3d bodyFrame(dBodyID body)
        {
            const dReal *p = dBodyGetPosition(body);
            const dReal *r = dBodyGetRotation(body);
            Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
            frame.translation() = Eigen::Vector3d(p[0], p[1], p[2]);
            for (int row = 0; row < 3; ++row)
                for (int col = 0; col < 3; ++col)
                    frame.linear()(row, col) = r[4 * row + col];
            return frame;
        }

        /** Puts body at frame with the velocities that carry it to next in dt seconds. */
        void moveKinematic(dBodyID body, const Eigen::Isometry3d &frame, const Eigen::Isometry3d &next,
                           double dt)
        {
            dMatrix3 rotation;
            ompl_phys::toOdeRotation(frame.linear(), rotation);
            dBodySetPosition(body, frame.translation().x(), frame.translation().y(), frame.translation().z());
            dBodySetRotation(body, rotation);
            const Eigen::Vector3d velocity = (next.translation() - frame.translation()) / dt;
            const Eigen::AngleAxisd turn(next.linear() * frame.linear().transpose());
            const Eigen::Vector3d spin = turn.axis() * (turn.angle() / dt);
            dBodySetLinearVel(body, velocity.x(), velocity.y(), velocity.z());
            dBodySetAngularVel(body, spin.x(), spin.y(), spin.z());
        }
    }  // namespace

    int surfaceUnder(const ompl_mm::Scene &scene, const Eigen::Vector3d &base)
    {
        for (std::size_t i = 0; i < scene.surfaces.size(); ++i)
        {
            const ompl_mm::SupportSurface &surface = scene.surfaces[i];
            if (surface.contains(base.x(), base.y()) && std::abs(base.z() - surface.height) < REST_SNAP)
                return static_cast<int>(i);
        }
        return -1;
    }

    /** ODE handles and what ODE keeps pointers into (geom tags, meshes, contact feedback). */
    struct PlanWorld::Handles
    {
        /** What a geom stands for, stored as the geom's data. */
        struct GeomTag
        {
            enum class Kind
            {
                Link,
                Object,
                Static
            };
            Kind kind{Kind::Static};
            unsigned int index{0};  ///< link or object index
            double friction{0.0};
        };

        /** A contact of a link with an object, whose force ODE writes after the step. */
        struct RobotContact
        {
            dJointFeedback feedback{};
            bool objectFirst{false};  ///< the object is the joint's first body
        };

        dWorldID world{nullptr};
        dSpaceID space{nullptr};
        dJointGroupID contacts{nullptr};
        std::vector<dBodyID> links;                  ///< per robot link, null for links without shapes
        std::vector<dBodyID> objects;                ///< per object
        std::vector<Eigen::Vector3d> centreOffsets;  ///< per object: shape centre above the base centre
        std::vector<char> held;
        std::vector<Eigen::Isometry3d> grasps;  ///< per held object: its frame in the tool's
        std::deque<GeomTag> tags;
        std::deque<OdeMesh> meshes;
        std::deque<RobotContact> robotContacts;  ///< of the last step
        std::vector<Eigen::Isometry3d> frames, nextFrames;
        double fallLimit{0.0};  ///< world z below which a falling object is stopped
        Eigen::Isometry3d tool{Eigen::Isometry3d::Identity()};

        ~Handles()
        {
            if (contacts)
                dJointGroupDestroy(contacts);
            if (space)
                dSpaceDestroy(space);  // destroys its geoms
            for (const OdeMesh &mesh : meshes)
                dGeomTriMeshDataDestroy(mesh.data);
            if (world)
                dWorldDestroy(world);  // destroys its bodies
        }
    };

    PlanWorld::PlanWorld(ompl_mm::ManipulationModelPtr model, const double *robot,
                         const std::vector<ompl_mm::ObjectPose> &poses, const WorldSettings &settings,
                         const std::vector<bool> &present)
        : model_(std::move(model)), settings_(settings), handles_(std::make_unique<Handles>())
    {
        if (poses.size() != model_->scene().objects.size())
            throw ompl::Exception("PlanWorld",
                                  "one pose per object is needed, got " + std::to_string(poses.size()));
        if (!present.empty() && present.size() != poses.size())
            throw ompl::Exception(
                "PlanWorld", "one presence flag per object is needed, got " + std::to_string(present.size()));
        ompl_phys::initialiseOde();
        dRandSetSeed(ODE_SEED);
        Handles &h = *handles_;
        using TagKind = Handles::GeomTag::Kind;
        const ompl_mm::Scene &scene = model_->scene();
        h.world = dWorldCreate();
        h.space = dSimpleSpaceCreate(nullptr);  // a fixed visiting order keeps runs identical
        h.contacts = dJointGroupCreate(0);
        dWorldSetGravity(h.world, 0.0, 0.0, settings_.gravity);
        dWorldSetQuickStepNumIterations(h.world, static_cast<int>(settings_.iterations));
        dWorldSetContactSurfaceLayer(h.world, SURFACE_LAYER);
        dWorldSetAutoDisableFlag(h.world, 0);

        double lowest = 0.0;
        for (const ompl_mm::SupportSurface &surface : scene.surfaces)
            lowest = std::min(lowest, surface.height);
        for (const ompl_mm::Obstacle &obstacle : scene.obstacles)
        {
            dGeomID geom = createGeom(h.space, obstacle.shape, h.meshes);
            ompl_phys::placeGeom(geom, obstacle.pose);
            dReal box[6];
            dGeomGetAABB(geom, box);
            lowest = std::min(lowest, static_cast<double>(box[4]));
            dGeomSetData(
                geom, &h.tags.emplace_back(Handles::GeomTag{TagKind::Static, 0, settings_.obstacleFriction}));
        }
        for (const ompl_mm::SupportSurface &surface : scene.surfaces)
        {
            if (!surface.obstacle.empty())
                continue;  // the obstacle's top
            const Eigen::Vector2d size = surface.max - surface.min;
            dGeomID slab = dCreateBox(h.space, size.x(), size.y(), SLAB_THICKNESS);
            const Eigen::Vector2d centre = 0.5 * (surface.min + surface.max);
            dGeomSetPosition(slab, centre.x(), centre.y(), surface.height - 0.5 * SLAB_THICKNESS);
            dGeomSetData(
                slab, &h.tags.emplace_back(Handles::GeomTag{TagKind::Static, 0, settings_.obstacleFriction}));
        }

        h.fallLimit = lowest - FALL_DEPTH;
        const std::vector<ompl_mm::Link> &links = model_->robot().links();
        h.links.assign(links.size(), nullptr);
        for (std::size_t i = 0; i < links.size(); ++i)
        {
            if (links[i].shapes.empty())
                continue;
            dBodyID body = dBodyCreate(h.world);
            dBodySetKinematic(body);
            for (const ompl_mm::LinkShape &linkShape : links[i].shapes)
            {
                dGeomID geom = createGeom(h.space, linkShape.shape, h.meshes);
                dGeomSetBody(geom, body);
                dMatrix3 rotation;
                ompl_phys::toOdeRotation(linkShape.origin.linear(), rotation);
                const Eigen::Vector3d &offset = linkShape.origin.translation();
                dGeomSetOffsetPosition(geom, offset.x(), offset.y(), offset.z());
                dGeomSetOffsetRotation(geom, rotation);
                dGeomSetData(
                    geom, &h.tags.emplace_back(Handles::GeomTag{TagKind::Link, static_cast<unsigned int>(i),
                                                                settings_.robotFriction}));
            }
            h.links[i] = body;
        }

        h.objects.assign(scene.objects.size(), nullptr);
        h.centreOffsets.assign(scene.objects.size(), Eigen::Vector3d::Zero());
        for (std::size_t i = 0; i < scene.objects.size(); ++i)
        {
            if (!present.empty() && !present[i])
                continue;
            const ompl_mm::MovableObject &object = scene.objects[i];
            dBodyID body = dBodyCreate(h.world);
            setMass(body, object.shape, object.mass);
            dGeomID geom = createGeom(h.space, object.shape, h.meshes);
            dGeomSetBody(geom, body);
            dGeomSetData(geom, &h.tags.emplace_back(Handles::GeomTag{
                                   TagKind::Object, static_cast<unsigned int>(i), object.friction}));
            h.centreOffsets[i] = Eigen::Vector3d(0.0, 0.0, 0.5 * object.shape.height());
            const Eigen::Isometry3d centre = poses[i].frame() * Eigen::Translation3d(h.centreOffsets[i]);
            moveKinematic(body, centre, centre, 1.0);  // at rest
            h.objects[i] = body;
        }
        h.held.assign(scene.objects.size(), 0);
        h.grasps.assign(scene.objects.size(), Eigen::Isometry3d::Identity());
        driveRobot(robot, robot, 1.0);
    }

    PlanWorld::~PlanWorld() = default;

    dBodyID PlanWorld::objectBody(unsigned int object) const
    {
        dBodyID body = handles_->objects.at(object);
        if (!body)
            throw ompl::Exception("PlanWorld", "object '" + model_->scene().objects[object].name +
                                                   "' was left out of this world");
        return body;
    }

    void PlanWorld::driveRobot(const double *from, const double *to, double dt)
    {
        Handles &h = *handles_;
        const Eigen::Isometry3d &base = model_->scene().robot.basePose;
        model_->robot().forwardKinematics(from, base, h.frames);
        model_->robot().forwardKinematics(to, base, h.nextFrames);
        for (std::size_t i = 0; i < h.links.size(); ++i)
            if (h.links[i])
                moveKinematic(h.links[i], h.frames[i], h.nextFrames[i], dt);
        h.tool = model_->toolFrame(from);
        placeHeld(h.tool, model_->toolFrame(to), dt);
    }

    void PlanWorld::placeHeld(const Eigen::Isometry3d &tool, const Eigen::Isometry3d &nextTool, double dt)
    {
        Handles &h = *handles_;
        for (std::size_t i = 0; i < h.objects.size(); ++i)
            if (h.held[i])
                moveKinematic(h.objects[i], tool * h.grasps[i], nextTool * h.grasps[i], dt);
    }

    void PlanWorld::hold(unsigned int object)
    {
        Handles &h = *handles_;
        dBodyID body = objectBody(object);
        h.grasps.at(object) = h.tool.inverse() * bodyFrame(body);
        h.held[object] = 1;
        dBodySetKinematic(body);
        placeHeld(h.tool, h.tool, 1.0);
    }

    void PlanWorld::release(unsigned int object)
    {
        Handles &h = *handles_;
        dBodyID body = objectBody(object);
        h.held.at(object) = 0;
        dBodySetDynamic(body);  // with the mass it had before it was held
        dBodySetLinearVel(body, 0.0, 0.0, 0.0);
        dBodySetAngularVel(body, 0.0, 0.0, 0.0);
    }

    void PlanWorld::isolate(unsigned int object)
    {
        const Handles &h = *handles_;
        for (std::size_t i = 0; i < h.objects.size(); ++i)
            if (h.objects[i] && i != object && !h.held[i])
                dBodyDisable(h.objects[i]);
        dRandSetSeed(ODE_SEED);
    }

    void PlanWorld::thaw()
    {
        for (dBodyID body : handles_->objects)
            if (body && dBodyGetPosition(body)[2] >= handles_->fallLimit)
                dBodyEnable(body);
    }

    bool PlanWorld::isHeld(unsigned int object) const
    {
        return handles_->held.at(object) != 0;
    }

    void PlanWorld::step(double dt)
    {
        Handles &h = *handles_;
        h.robotContacts.clear();
        collide();
        dWorldQuickStep(h.world, dt);
        dJointGroupEmpty(h.contacts);
        for (dBodyID body : h.objects)
            if (body && dBodyGetPosition(body)[2] < h.fallLimit)
                dBodyDisable(body);  // fell out of the world: stays where it is
    }

    void PlanWorld::collide()
    {
        dSpaceCollide(handles_->space, this,
                      [](void *data, dGeomID a, dGeomID b)
                      { static_cast<PlanWorld *>(data)->handlePair(a, b); });
    }

    void PlanWorld::handlePair(void *geomA, void *geomB)
    {
        auto a = static_cast<dGeomID>(geomA);
        auto b = static_cast<dGeomID>(geomB);
        dBodyID bodyA = dGeomGetBody(a);
        dBodyID bodyB = dGeomGetBody(b);
        const bool dynamicA = bodyA && !dBodyIsKinematic(bodyA);
        const bool dynamicB = bodyB && !dBodyIsKinematic(bodyB);
        if (!dynamicA && !dynamicB)
            return;  // nothing here can move the other
        std::array<dContactGeom, MAX_CONTACT_POINTS> points;
        const int count = dCollide(
            a, b, static_cast<int>(std::min<unsigned int>(settings_.maxContactPoints, MAX_CONTACT_POINTS)),
            points.data(), sizeof(dContactGeom));
        if (count == 0)
            return;
        using TagKind = Handles::GeomTag::Kind;
        const auto *tagA = static_cast<const Handles::GeomTag *>(dGeomGetData(a));
        const auto *tagB = static_cast<const Handles::GeomTag *>(dGeomGetData(b));
        const bool robotOnObject = (tagA->kind == TagKind::Link && tagB->kind == TagKind::Object) ||
                                   (tagB->kind == TagKind::Link && tagA->kind == TagKind::Object);
        dContact contact{};
        contact.surface.mode = dContactApprox1;
        contact.surface.mu = std::sqrt(tagA->friction * tagB->friction);
        for (int i = 0; i < count; ++i)
        {
            contact.geom = points[static_cast<std::size_t>(i)];
            dJointID joint = dJointCreateContact(handles_->world, handles_->contacts, &contact);
            dJointAttach(joint, bodyA, bodyB);
            if (robotOnObject)
            {
                Handles::RobotContact &robotContact = handles_->robotContacts.emplace_back();
                robotContact.objectFirst = tagA->kind == TagKind::Object;
                dJointSetFeedback(joint, &robotContact.feedback);
            }
        }
    }

    ompl_mm::ObjectPose PlanWorld::objectPose(unsigned int object) const
    {
        const Eigen::Isometry3d frame = bodyFrame(objectBody(object));
        ompl_mm::ObjectPose pose;
        pose.position = frame * (-handles_->centreOffsets[object]);
        pose.yaw = std::atan2(frame.linear()(1, 0), frame.linear()(0, 0));
        return pose;
    }

    double PlanWorld::objectTilt(unsigned int object) const
    {
        const double up = bodyFrame(objectBody(object)).linear()(2, 2);
        return std::acos(std::clamp(up, -1.0, 1.0));
    }

    double PlanWorld::objectSpeed(unsigned int object) const
    {
        const dReal *v = dBodyGetLinearVel(objectBody(object));
        return Eigen::Vector3d(v[0], v[1], v[2]).norm();
    }

    bool PlanWorld::atRest(double speed, double spin) const
    {
        const Handles &h = *handles_;
        for (std::size_t i = 0; i < h.objects.size(); ++i)
        {
            dBodyID body = h.objects[i];
            if (!body || h.held[i] || !dBodyIsEnabled(body))
                continue;
            const dReal *v = dBodyGetLinearVel(body);
            const dReal *w = dBodyGetAngularVel(body);
            if (Eigen::Vector3d(v[0], v[1], v[2]).norm() >= speed ||
                Eigen::Vector3d(w[0], w[1], w[2]).norm() >= spin)
                return false;
        }
        return true;
    }

    Eigen::Vector3d PlanWorld::robotContactForce() const
    {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for (const Handles::RobotContact &contact : handles_->robotContacts)
        {
            const dReal *f = contact.objectFirst ? contact.feedback.f1 : contact.feedback.f2;
            sum += Eigen::Vector3d(f[0], f[1], f[2]);
        }
        return sum;
    }
}  // namespace ompl_mmphys
