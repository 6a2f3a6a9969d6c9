#include "ompl_phys/io/PhysicsPathFile.h"

#include <iomanip>
#include <locale>

namespace ompl_phys
{
    void writeSimulatedPathFile(std::ostream &out, const PhysicsSetup &setup, const SimulatedPath &simulated)
    {
        const PhysicsScene &scene = setup.scene();
        const PhysicsWorld &world = setup.world();
        const RobotTrajectory &robot = simulated.robot;
        out.imbue(std::locale::classic());
        out << std::setprecision(17) << "# step_s " << robot.stepDuration << " goal_x "
            << scene.goal.centre.x() << " goal_y " << scene.goal.centre.y() << " goal_radius "
            << scene.goal.radius << '\n';
        out << "# sample t move fx fy fz";
        for (std::size_t i = 0; i < world.movingBodyCount(); ++i)
        {
            const std::string &name = world.movingBodyName(i);
            out << ' ' << name << ".x " << name << ".y " << name << ".z";
        }
        out << '\n';
        // the move applied from each sample to the next, or -1
        std::vector<long> moveAt(simulated.states.size(), -1);
        std::size_t sample = 0;
        for (std::size_t i = 0; i < robot.moves.size(); ++i)
            for (std::size_t k = 0; k < robot.moves[i].steps; ++k)
                moveAt.at(sample++) = static_cast<long>(i);
        for (std::size_t k = 0; k < simulated.states.size(); ++k)
        {
            const Eigen::Vector3d force = moveAt[k] >= 0
                                              ? robot.moves[static_cast<std::size_t>(moveAt[k])].force
                                              : Eigen::Vector3d::Zero();
            out << k << ' ' << static_cast<double>(k) * robot.stepDuration << ' ' << moveAt[k] << ' '
                << force.x() << ' ' << force.y() << ' ' << force.z();
            for (const BodyState &body : simulated.states[k])
                out << ' ' << body.position.x() << ' ' << body.position.y() << ' ' << body.position.z();
            out << '\n';
        }
    }
}  // namespace ompl_phys
