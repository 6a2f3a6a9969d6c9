#include "ompl_mm/io/PathFile.h"

#include <ompl/base/SpaceInformation.h>

#include <algorithm>
#include <iomanip>
#include <string>
#include <vector>

namespace ompl_mm
{
    void writePathFile(std::ostream &out, const ManipulationPath &path, const ExtraColumns &extra)
    {
        if (!extra.values.empty() &&
            (extra.values.size() != path.getStateCount() ||
             std::any_of(extra.values.begin(), extra.values.end(),
                         [&](const std::vector<double> &row) { return row.size() != extra.names.size(); })))
            throw ompl::Exception("writePathFile", "extra columns need one row of " +
                                                       std::to_string(extra.names.size()) +
                                                       " values per waypoint");
        const auto *space = path.getSpaceInformation()->getStateSpace()->as<ManipulationStateSpace>();
        const ManipulationModel &model = *space->model();
        out << "# segment object tool.x tool.y tool.z";
        for (unsigned int j = 0; j < model.dof(); ++j)
            out << ' ' << model.robot().variableJoint(j).name;
        std::vector<const Joint *> mimics;  // written after the planning joints, for readers that
                                            // pose the robot joint by joint
        for (const Joint &joint : model.robot().joints())
            if (joint.mimics >= 0)
            {
                mimics.push_back(&joint);
                out << ' ' << joint.name;
            }
        for (const MovableObject &object : model.scene().objects)
            out << ' ' << object.name << ".x " << object.name << ".y " << object.name << ".z " << object.name
                << ".yaw";
        for (const std::string &name : extra.names)
            out << ' ' << name;
        out << '\n' << std::setprecision(10);
        const std::vector<SegmentLabel> &labels = path.labels();  // checked once, not per waypoint
        for (std::size_t i = 0; i < path.getStateCount(); ++i)
        {
            const ompl::base::State *state = path.getState(i);
            if (i == 0)
                out << "start -";
            else
            {
                const SegmentLabel &label = labels[i - 1];
                out << primitiveKindName(label.kind) << ' '
                    << (label.object >= 0 ? model.scene().objects[label.object].name : std::string("-"));
            }
            const Eigen::Vector3d tool = space->toolPosition(state);
            out << ' ' << tool.x() << ' ' << tool.y() << ' ' << tool.z();
            for (unsigned int j = 0; j < model.dof(); ++j)
                out << ' ' << space->robotValues(state)[j];
            for (const Joint *mimic : mimics)
                out << ' ' << mimic->value(space->robotValues(state));
            for (unsigned int o = 0; o < model.objectCount(); ++o)
            {
                const ObjectPose pose = space->objectPose(state, o);
                out << ' ' << pose.position.x() << ' ' << pose.position.y() << ' ' << pose.position.z() << ' '
                    << pose.yaw;
            }
            if (!extra.values.empty())
                for (double value : extra.values[i])
                    out << ' ' << value;
            out << '\n';
        }
    }
}  // namespace ompl_mm
