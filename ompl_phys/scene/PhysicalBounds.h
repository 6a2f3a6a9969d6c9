/* The ranges of a physics scene's quantities within which ODE simulates it correctly and a control's
   propagation stays short; the loader rejects anything outside them at its line
   (docs/scene-format.md, "Physical bounds"). Lengths and positions are bounded for every scene by
   ompl_core's reader (MIN_LENGTH, MAX_LENGTH, MAX_LIST_VALUE). */
#pragma once

namespace ompl_phys::bounds
{
    /** Masses, kg: ODE's QuickStep loses accuracy for mass ratios beyond about 1e6, and masses like
        1e200 overflow the inertia tensor and abort ODE. */
    constexpr double MIN_MASS = 1e-3;
    constexpr double MAX_MASS = 1e3;

    /** Gravity, m/s² (downwards, so from -MAX_GRAVITY to 0): about ten times the earth's. */
    constexpr double MAX_GRAVITY = 100.0;

    /** The largest force on the robot, N: on MIN_MASS it would still move less than a metre per
        millisecond step. */
    constexpr double MAX_FORCE = 1e4;

    /** Speed limits, m/s and rad/s. */
    constexpr double MAX_SPEED = 100.0;
    constexpr double MAX_ANGULAR_SPEED = 1000.0;

    /** Friction coefficients: ODE's Coulomb friction; above this a contact cannot slide anyway. */
    constexpr double MAX_FRICTION = 100.0;

    /** The propagation step, s. */
    constexpr double MAX_STEP = 1.0;

    /** ODE sub-steps per control at most (max_steps × substeps): one control then takes at most
        about 20 ms of ODE time, so a planner's time limit is not overrun by one propagation. */
    constexpr unsigned int MAX_SUBSTEPS_PER_CONTROL = 2000;
}  // namespace ompl_phys::bounds
