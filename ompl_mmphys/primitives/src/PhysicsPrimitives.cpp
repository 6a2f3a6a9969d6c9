#include "ompl_mmphys/primitives/PhysicsPrimitives.h"

#include "ompl_core/io/InputError.h"
#include "ompl_mm/primitives/ArmPush.h"
#include "ompl_mm/primitives/PushMobile.h"
#include "ompl_mmphys/primitives/PhysicsPush.h"

namespace ompl_mmphys
{
    namespace
    {
        /** The parameters only a physics-aware push reads. */
        const char *const PHYSICS_PARAMETERS[] = {"model", "push_precision", "push_corrections"};

        /** How far a push's tool point stands from the object it pushes, per object. */
        std::function<double(unsigned int)> standoffOf(const ompl_mm::PrimitivePtr &push)
        {
            if (auto mobile = std::dynamic_pointer_cast<ompl_mm::PushMobile>(push))
                return [mobile](unsigned int object) { return mobile->standoff(object); };
            if (auto arm = std::dynamic_pointer_cast<ompl_mm::ArmPush>(push))
                return [arm](unsigned int) { return arm->settings().standoff; };
            return {};
        }

        /** The builder of `kinematic`'s type that also knows model="physics". */
        ompl_mm::PrimitiveFactory::Builder physicsAware(ompl_mm::PrimitiveFactory::Builder kinematic)
        {
            return [kinematic](const ompl_mm::ManipulationStateSpace *space,
                               const ompl_mm::PrimitiveParameters &params) -> ompl_mm::PrimitivePtr
            {
                if (params.text("model", "kinematic") != "physics")
                    return kinematic(space, params);
                PhysicsPush::Settings settings;
                settings.precision = params.number("push_precision", settings.precision);
                if (!(settings.precision > 0.0))
                    throw ompl_core::InputError(params.spec().where, "<" + params.spec().type +
                                                                         "> parameter 'push_precision' must be "
                                                                         "positive, got '" +
                                                                         params.spec().params.at("push_precision") +
                                                                         "'");
                settings.corrections = params.count("push_corrections", settings.corrections, 0, 20);
                // the kinematic push from the other parameters, which it checks itself
                ompl_mm::PrimitiveSpec spec = params.spec();
                for (const char *name : PHYSICS_PARAMETERS)
                    spec.params.erase(name);
                const ompl_mm::PrimitiveParameters own(spec, params.inverseKinematics());
                ompl_mm::PrimitivePtr push = kinematic(space, own);
                own.rejectUnread();
                for (const auto &[name, value] : spec.params)
                    params.text(name, value);  // read, through the kinematic push
                return std::make_shared<PhysicsPush>(space, push, standoffOf(push), settings);
            };
        }
    }  // namespace

    ompl_mm::PrimitiveFactory physicsPrimitiveFactory()
    {
        ompl_mm::PrimitiveFactory factory;
        for (const char *type : {"push_mobile", "push_interior", "push_exterior", "push_frontal"})
            factory.registerType(type, physicsAware(factory.builder(type)));
        return factory;
    }
}  // namespace ompl_mmphys
