#include "ompl_mm/model/ManipulationModel.h"

#include "ompl_core/io/InputError.h"

namespace ompl_mm
{
    ManipulationModel::ManipulationModel(Scene scene, RobotModel robot)
        : scene_(std::move(scene)), robot_(std::move(robot))
    {
        try
        {
            toolLink_ = robot_.linkIndex(scene_.robot.toolLink);
        }
        catch (const ompl::Exception &e)
        {
            throw ompl_core::InputError(scene_.robot.where, e.what());
        }
        try
        {
            toolPointChain_.emplace(robot_, toolLink_, scene_.robot.toolOffset);
        }
        catch (const ompl::Exception &e)
        {
            throw ompl_core::InputError(scene_.robot.where, e.what());
        }
        for (const ToolFrame &tool : scene_.robot.tools)
        {
            const int link = robot_.findLink(tool.link);
            if (link < 0)
                throw ompl_core::InputError(tool.where, "tool frame '" + tool.name + "' names link '" +
                                                            tool.link + "', which robot '" + robot_.name() +
                                                            "' does not have");
            try
            {
                toolChains_.emplace_back(tool.name, KinematicChain(robot_, link, tool.pose));
            }
            catch (const ompl::Exception &e)
            {
                throw ompl_core::InputError(tool.where, e.what());
            }
        }
    }

    const KinematicChain &ManipulationModel::toolChain(const std::string &name) const
    {
        for (const auto &[toolName, chain] : toolChains_)
            if (toolName == name)
                return chain;
        throw ompl::Exception("ManipulationModel", "the scene declares no tool frame '" + name + "'");
    }

    Eigen::Isometry3d ManipulationModel::toolFrame(const double *q) const
    {
        // the chain, its fixed transforms folded together and its turns about coordinate axes,
        // rather than a transform product per link: tool paths and carried objects ask for it at
        // every state
        return toolPointChain_->toolPose(q, scene_.robot.basePose);
    }
}  // namespace ompl_mm
