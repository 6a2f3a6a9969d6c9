#include "ompl_phys/world/PhysicsWorld.h"

#include "ompl_phys/world/OdeGeometry.h"

#include <ode/ode.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <array>
#include <deque>

namespace ompl_phys
{
    namespace
    {
        /** Seed given to ODE's generator before every simulation from a written state. */
        constexpr unsigned long ODE_SEED = 1;
        /** Contacts are created this far before geometry touches; damps resting jitter, metres. */
        constexpr double SURFACE_LAYER = 0.001;
        /** Most contact points dCollide may return for one pair. */
        constexpr int MAX_CONTACT_POINTS = 16;
    }  // namespace

    /** ODE handles and the arrays ODE keeps pointers into (tags, convex data). */
    struct PhysicsWorld::Handles
    {
        /** What a geom stands for, stored as the geom's data. */
        struct GeomTag
        {
            enum class Kind
            {
                Floor,
                Robot,
                Body
            };
            Kind kind{Kind::Floor};
            std::size_t sceneBody{0};  ///< for Kind::Body
        };

        dWorldID world{nullptr};
        dSpaceID space{nullptr};
        dJointGroupID contacts{nullptr};
        std::vector<dBodyID> bodies;  // moving bodies, robot first
        std::vector<GeomTag> tags;    // reserved up front: geoms point into it
        std::deque<ConvexPrismData> prisms;

        ~Handles()
        {
            if (contacts)
                dJointGroupDestroy(contacts);
            if (space)
                dSpaceDestroy(space);  // destroys its geoms
            if (world)
                dWorldDestroy(world);  // destroys its bodies
        }
    };

    PhysicsWorld::PhysicsWorld(PhysicsScenePtr scene)
        : scene_(std::move(scene)), handles_(std::make_unique<Handles>())
    {
        initialiseOde();
        movable_ = scene_->movableBodies();
        Handles &h = *handles_;
        using TagKind = Handles::GeomTag::Kind;
        h.world = dWorldCreate();
        h.space = dSimpleSpaceCreate(nullptr);  // few geoms; a fixed visiting order keeps runs identical
        h.contacts = dJointGroupCreate(0);
        dWorldSetGravity(h.world, 0.0, 0.0, scene_->contact.gravity);
        dWorldSetQuickStepNumIterations(h.world, static_cast<int>(scene_->contact.iterations));
        dWorldSetContactSurfaceLayer(h.world, SURFACE_LAYER);
        dWorldSetAutoDisableFlag(h.world, 0);

        h.tags.reserve(2 + scene_->bodies.size());
        h.tags.push_back({TagKind::Floor, 0});
        dGeomSetData(dCreatePlane(h.space, 0.0, 0.0, 1.0, 0.0), &h.tags.back());

        dBodyID robot = dBodyCreate(h.world);
        dMass robotMass;
        dMassSetSphereTotal(&robotMass, scene_->robot.mass, scene_->robot.radius);
        dBodySetMass(robot, &robotMass);
        dGeomID robotGeom = dCreateSphere(h.space, scene_->robot.radius);
        dGeomSetBody(robotGeom, robot);
        h.tags.push_back({TagKind::Robot, 0});
        dGeomSetData(robotGeom, &h.tags.back());
        h.bodies.push_back(robot);

        for (std::size_t i = 0; i < scene_->bodies.size(); ++i)
        {
            const PhysicsBody &body = scene_->bodies[i];
            const bool prism = body.shape.kind == PhysicsShape::Kind::Prism;
            if (prism && body.kind != BodyKind::Fixed)
                throw ompl::Exception("PhysicsWorld",
                                      "body '" + body.name + "': a prism can only be a fixed body");
            dGeomID geom = createShapeGeom(h.space, body.shape, h.prisms);
            h.tags.push_back({TagKind::Body, i});
            dGeomSetData(geom, &h.tags.back());
            if (body.kind == BodyKind::Fixed)
            {
                placeGeom(geom, body.start);
                continue;
            }
            dBodyID dynamic = dBodyCreate(h.world);
            setShapeMass(dynamic, body.shape, body.mass);
            dGeomSetBody(geom, dynamic);
            h.bodies.push_back(dynamic);
        }
        setStates(startStates());
    }

    PhysicsWorld::~PhysicsWorld() = default;

    const std::string &PhysicsWorld::movingBodyName(std::size_t movingIndex) const
    {
        return movingIndex == 0 ? scene_->robot.name : scene_->bodies[sceneBodyOf(movingIndex)].name;
    }

    BodyStates PhysicsWorld::startStates() const
    {
        BodyStates states(movingBodyCount());
        states[0].position = scene_->robot.start;
        for (std::size_t i = 1; i < states.size(); ++i)
        {
            const Eigen::Isometry3d &start = scene_->bodies[sceneBodyOf(i)].start;
            states[i].position = start.translation();
            states[i].orientation = Eigen::Quaterniond(start.linear());
        }
        return states;
    }

    void PhysicsWorld::setStates(const BodyStates &states)
    {
        for (std::size_t i = 0; i < handles_->bodies.size(); ++i)
        {
            dBodyID body = handles_->bodies[i];
            const BodyState &s = states[i];
            dBodySetPosition(body, s.position.x(), s.position.y(), s.position.z());
            const dQuaternion q = {s.orientation.w(), s.orientation.x(), s.orientation.y(),
                                   s.orientation.z()};
            dBodySetQuaternion(body, q);
            dBodySetLinearVel(body, s.linearVelocity.x(), s.linearVelocity.y(), s.linearVelocity.z());
            dBodySetAngularVel(body, s.angularVelocity.x(), s.angularVelocity.y(), s.angularVelocity.z());
            dBodySetForce(body, 0.0, 0.0, 0.0);
            dBodySetTorque(body, 0.0, 0.0, 0.0);
        }
    }

    void PhysicsWorld::readStates(BodyStates &states) const
    {
        states.resize(handles_->bodies.size());
        for (std::size_t i = 0; i < handles_->bodies.size(); ++i)
        {
            dBodyID body = handles_->bodies[i];
            const dReal *p = dBodyGetPosition(body);
            const dReal *q = dBodyGetQuaternion(body);
            const dReal *v = dBodyGetLinearVel(body);
            const dReal *w = dBodyGetAngularVel(body);
            states[i].position = Eigen::Vector3d(p[0], p[1], p[2]);
            states[i].orientation = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
            states[i].linearVelocity = Eigen::Vector3d(v[0], v[1], v[2]);
            states[i].angularVelocity = Eigen::Vector3d(w[0], w[1], w[2]);
        }
    }

    void PhysicsWorld::step(const Eigen::Vector2d &force, double dt)
    {
        dBodyAddForce(handles_->bodies[0], force.x(), force.y(), 0.0);
        createContacts_ = true;
        collide();
        dWorldQuickStep(handles_->world, dt);
        dJointGroupEmpty(handles_->contacts);
    }

    double PhysicsWorld::detectContacts()
    {
        createContacts_ = false;
        collide();
        return deepest_;
    }

    void PhysicsWorld::resetRandomSeed()
    {
        dRandSetSeed(ODE_SEED);
    }

    void PhysicsWorld::collide()
    {
        touches_.clear();
        deepest_ = 0.0;
        dSpaceCollide(handles_->space, this,
                      [](void *data, dGeomID a, dGeomID b)
                      { static_cast<PhysicsWorld *>(data)->handlePair(a, b); });
        std::sort(touches_.begin(), touches_.end());
        touches_.erase(std::unique(touches_.begin(), touches_.end()), touches_.end());
    }

    void PhysicsWorld::handlePair(void *geomA, void *geomB)
    {
        auto a = static_cast<dGeomID>(geomA);
        auto b = static_cast<dGeomID>(geomB);
        dBodyID bodyA = dGeomGetBody(a);
        dBodyID bodyB = dGeomGetBody(b);
        if (!bodyA && !bodyB)
            return;  // static geometry never moves
        std::array<dContactGeom, MAX_CONTACT_POINTS> points;
        const int count = dCollide(a, b, static_cast<int>(scene_->contact.maxContacts), points.data(),
                                   sizeof(dContactGeom));
        if (count == 0)
            return;
        using TagKind = Handles::GeomTag::Kind;
        const auto *tagA = static_cast<const Handles::GeomTag *>(dGeomGetData(a));
        const auto *tagB = static_cast<const Handles::GeomTag *>(dGeomGetData(b));
        if (tagA->kind == TagKind::Robot && tagB->kind == TagKind::Body)
            touches_.push_back(tagB->sceneBody);
        if (tagB->kind == TagKind::Robot && tagA->kind == TagKind::Body)
            touches_.push_back(tagA->sceneBody);
        for (int i = 0; i < count; ++i)
            deepest_ = std::max(deepest_, points[i].depth);
        if (!createContacts_)
            return;

        const bool robotOnFloor = (tagA->kind == TagKind::Robot && tagB->kind == TagKind::Floor) ||
                                  (tagB->kind == TagKind::Robot && tagA->kind == TagKind::Floor);
        dContact contact{};
        contact.surface.mode = dContactSoftERP | dContactSoftCFM | dContactApprox1;
        contact.surface.mu = robotOnFloor ? scene_->materials.robotFloor : scene_->materials.defaultMu;
        contact.surface.soft_erp = scene_->contact.erp;
        contact.surface.soft_cfm = scene_->contact.cfm;
        for (int i = 0; i < count; ++i)
        {
            contact.geom = points[i];
            dJointID joint = dJointCreateContact(handles_->world, handles_->contacts, &contact);
            dJointAttach(joint, bodyA, bodyB);
        }
    }
}  // namespace ompl_phys
