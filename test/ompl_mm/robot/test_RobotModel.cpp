// Tests for RobotModel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "ompl_core/io/InputFile.h"
#include "ompl_mm/robot/RobotModel.h"

#include "common/MobileBlocked.h"

namespace ompl_mm
{
    namespace
    {
        using test::inputErrorOf;

        const std::string ROBOTS_DIR = std::string(OMPL_MM_TEST_DATA_DIR) + "/robots/";
        const double PI = std::acos(-1.0);
        const double TOLERANCE = 1e-12;

        RobotModel load(const std::string &file)
        {
            return RobotModel::fromUrdfFile(ROBOTS_DIR + file);
        }

        double maxDifference(const Eigen::Isometry3d &a, const Eigen::Isometry3d &b)
        {
            return (a.matrix() - b.matrix()).cwiseAbs().maxCoeff();
        }

        /** Uniform joint values within the model's limits. */
        std::vector<double> randomJoints(const RobotModel &robot, std::mt19937 &rng)
        {
            std::vector<double> q(robot.dof());
            for (unsigned int i = 0; i < robot.dof(); ++i)
            {
                const Joint &joint = robot.variableJoint(i);
                q[i] = std::uniform_real_distribution<double>(joint.lower, joint.upper)(rng);
            }
            return q;
        }

        /** A base pose away from the identity, so tests see that it is applied. */
        Eigen::Isometry3d someBase()
        {
            Eigen::Isometry3d base = Eigen::Isometry3d::Identity();
            base.translate(Eigen::Vector3d(0.4, -1.2, 0.3));
            base.rotate(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()));
            return base;
        }

        /** Standard DH link transform Rz(theta) Tz(d) Tx(a) Rx(alpha), written out entry by entry. */
        Eigen::Matrix4d dhMatrix(double theta, double d, double a, double alpha)
        {
            const double ct = std::cos(theta), st = std::sin(theta);
            const double ca = std::cos(alpha), sa = std::sin(alpha);
            Eigen::Matrix4d m;
            m << ct, -st * ca, st * sa, a * ct,  //
                st, ct * ca, -ct * sa, a * st,   //
                0.0, sa, ca, d,                  //
                0.0, 0.0, 0.0, 1.0;
            return m;
        }

        /** A robot with one joint "shoulder" from "base" to "arm"; arm carries the given geometry. */
        std::string oneJointUrdf(const std::string &type, const std::string &jointBody,
                                 const std::string &geometry = "<sphere radius=\"0.1\"/>")
        {
            return "<?xml version=\"1.0\"?>\n"
                   "<robot name=\"bad\">\n"
                   "  <link name=\"base\"/>\n"
                   "  <link name=\"arm\">\n"
                   "    <collision>\n"
                   "      <geometry>" +
                   geometry +
                   "</geometry>\n"
                   "    </collision>\n"
                   "  </link>\n"
                   "  <joint name=\"shoulder\" type=\"" +
                   type +
                   "\">\n"
                   "    <parent link=\"base\"/>\n"
                   "    <child link=\"arm\"/>\n" +
                   jointBody +
                   "  </joint>\n"
                   "</robot>\n";
        }

        const std::string REVOLUTE_LIMITS =
            "    <limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>\n";

        TEST(RobotModel, PlanarArmToolMatchesAnalyticPosition)
        {
            const RobotModel robot = load("planar_2link.urdf");
            const int tool = robot.linkIndex("tool");
            const double l1 = 0.5, l2 = 0.3;
            for (double q1 : {-2.5, -1.0, 0.0, 0.3, 1.7, 2.9})
                for (double q2 : {-2.4, -0.5, 0.0, 0.8, 2.2})
                {
                    const double q[] = {q1, q2};
                    const Eigen::Isometry3d frame = robot.linkFrame(q, Eigen::Isometry3d::Identity(), tool);
                    EXPECT_NEAR(frame.translation().x(), l1 * std::cos(q1) + l2 * std::cos(q1 + q2),
                                TOLERANCE);
                    EXPECT_NEAR(frame.translation().y(), l1 * std::sin(q1) + l2 * std::sin(q1 + q2),
                                TOLERANCE);
                    EXPECT_NEAR(frame.translation().z(), 0.0, TOLERANCE);
                    // the tool x axis points along the second link
                    const Eigen::Vector3d toolX = frame.linear().col(0);
                    EXPECT_NEAR(toolX.x(), std::cos(q1 + q2), TOLERANCE);
                    EXPECT_NEAR(toolX.y(), std::sin(q1 + q2), TOLERANCE);
                }
        }

        TEST(RobotModel, MobileBaseFrameIsBaseTranslated)
        {
            const RobotModel robot = load("mobile_base_xy.urdf");
            const Eigen::Isometry3d base = someBase();
            const int body = robot.linkIndex("body");
            const int slider = robot.linkIndex("slider");
            for (double qx : {-2.9, -0.4, 0.0, 1.3})
                for (double qy : {-1.8, 0.0, 0.6, 1.9})
                {
                    const double q[] = {qx, qy};
                    const Eigen::Isometry3d expectedBody = base * Eigen::Translation3d(qx, qy, 0.0);
                    const Eigen::Isometry3d expectedSlider = base * Eigen::Translation3d(qx, 0.0, 0.0);
                    EXPECT_LT(maxDifference(robot.linkFrame(q, base, body), expectedBody), TOLERANCE);
                    EXPECT_LT(maxDifference(robot.linkFrame(q, base, slider), expectedSlider), TOLERANCE);
                }
        }

        TEST(RobotModel, SevenDofArmFlangeMatchesDhProduct)
        {
            const RobotModel robot = load("kuka_lwr_dh.urdf");
            ASSERT_EQ(robot.dof(), 7u);
            const double d[] = {0.31, 0.0, 0.40, 0.0, 0.39, 0.0, 0.0};
            const double alphaDegrees[] = {90.0, -90.0, -90.0, 90.0, 90.0, -90.0, 0.0};
            const int flange = robot.linkIndex("flange");
            const Eigen::Isometry3d base = someBase();
            std::mt19937 rng(20240611);
            for (int trial = 0; trial < 200; ++trial)
            {
                const std::vector<double> q = randomJoints(robot, rng);
                Eigen::Matrix4d expected = base.matrix();
                for (int i = 0; i < 7; ++i)
                    expected = expected * dhMatrix(q[i], d[i], 0.0, alphaDegrees[i] * PI / 180.0);
                const Eigen::Isometry3d frame = robot.linkFrame(q.data(), base, flange);
                EXPECT_LT((frame.matrix() - expected).cwiseAbs().maxCoeff(), TOLERANCE) << "trial " << trial;
            }
        }

        TEST(RobotModel, ForwardKinematicsAgreesWithLinkFrameForEveryLink)
        {
            std::mt19937 rng(7);
            const Eigen::Isometry3d base = someBase();
            for (const char *file :
                 {"planar_2link.urdf", "mobile_base_xy.urdf", "kuka_lwr_dh.urdf", "torso_tree.urdf"})
            {
                const RobotModel robot = load(file);
                std::vector<Eigen::Isometry3d> frames;
                for (int trial = 0; trial < 20; ++trial)
                {
                    const std::vector<double> q = randomJoints(robot, rng);
                    robot.forwardKinematics(q.data(), base, frames);
                    ASSERT_EQ(frames.size(), robot.links().size());
                    EXPECT_LT(maxDifference(frames[0], base), TOLERANCE);
                    for (std::size_t link = 0; link < frames.size(); ++link)
                        EXPECT_LT(maxDifference(frames[link],
                                                robot.linkFrame(q.data(), base, static_cast<int>(link))),
                                  TOLERANCE)
                            << file << " link " << robot.links()[link].name;
                }
            }
        }

        TEST(RobotModel, ReadsStructureLimitsAndShapes)
        {
            const RobotModel robot = load("planar_2link.urdf");
            EXPECT_EQ(robot.name(), "planar_2link");
            ASSERT_EQ(robot.dof(), 2u);
            ASSERT_EQ(robot.links().size(), 4u);
            ASSERT_EQ(robot.joints().size(), 3u);

            const std::vector<std::string> names = {"base", "link1", "link2", "tool"};
            for (std::size_t i = 0; i < names.size(); ++i)
            {
                const Link &link = robot.links()[i];
                EXPECT_EQ(link.name, names[i]);
                EXPECT_EQ(link.parent, static_cast<int>(i) - 1);
                EXPECT_EQ(robot.linkIndex(names[i]), static_cast<int>(i));
            }
            EXPECT_EQ(robot.links()[0].joint, -1);
            EXPECT_EQ(robot.joints()[robot.links()[3].joint].name, "tool_joint");

            const Joint &joint1 = robot.variableJoint(0);
            EXPECT_EQ(joint1.name, "joint1");
            EXPECT_EQ(joint1.type, Joint::Type::Revolute);
            EXPECT_EQ(joint1.variable, 0);
            EXPECT_EQ(joint1.lower, -3.0);
            EXPECT_EQ(joint1.upper, 3.0);
            const Joint &joint2 = robot.variableJoint(1);
            EXPECT_EQ(joint2.name, "joint2");
            EXPECT_EQ(joint2.variable, 1);
            EXPECT_EQ(joint2.lower, -2.5);
            EXPECT_EQ(joint2.upper, 2.5);
            EXPECT_LT((joint2.axis - Eigen::Vector3d::UnitZ()).norm(), TOLERANCE);  // written as 0 0 2
            EXPECT_EQ(robot.joints()[robot.links()[3].joint].type, Joint::Type::Fixed);
            EXPECT_EQ(robot.joints()[robot.links()[3].joint].variable, -1);

            ASSERT_EQ(robot.links()[0].shapes.size(), 1u);
            EXPECT_EQ(robot.links()[0].shapes[0].shape.kind, Shape::Kind::Box);
            EXPECT_LT((robot.links()[0].shapes[0].shape.boxSize - Eigen::Vector3d(0.2, 0.2, 0.1)).norm(),
                      TOLERANCE);

            ASSERT_EQ(robot.links()[1].shapes.size(), 1u);
            const LinkShape &cylinder = robot.links()[1].shapes[0];
            EXPECT_EQ(cylinder.shape.kind, Shape::Kind::Cylinder);
            EXPECT_EQ(cylinder.shape.radius, 0.05);
            EXPECT_EQ(cylinder.shape.length, 0.5);
            EXPECT_LT((cylinder.origin.translation() - Eigen::Vector3d(0.25, 0.0, 0.0)).norm(), TOLERANCE);
            // pitched by 90 degrees, the cylinder's z axis lies along the link's x axis
            EXPECT_LT((cylinder.origin.linear().col(2) - Eigen::Vector3d::UnitX()).norm(), 1e-9);

            ASSERT_EQ(robot.links()[2].shapes.size(), 2u);
            EXPECT_EQ(robot.links()[2].shapes[0].shape.kind, Shape::Kind::Box);
            const LinkShape &sphere = robot.links()[2].shapes[1];
            EXPECT_EQ(sphere.shape.kind, Shape::Kind::Sphere);
            EXPECT_EQ(sphere.shape.radius, 0.04);
            EXPECT_LT((sphere.origin.translation() - Eigen::Vector3d(0.3, 0.0, 0.0)).norm(), TOLERANCE);
            EXPECT_TRUE(robot.links()[3].shapes.empty());
        }

        TEST(RobotModel, TreeIsParentsFirstWithVariablesInFileOrder)
        {
            const RobotModel robot = load("torso_tree.urdf");
            ASSERT_EQ(robot.dof(), 5u);
            EXPECT_EQ(robot.links()[0].name, "torso");
            for (std::size_t i = 1; i < robot.links().size(); ++i)
                EXPECT_LT(robot.links()[i].parent, static_cast<int>(i)) << robot.links()[i].name;

            // depth first, siblings in file order: each arm's variables are contiguous
            const std::vector<std::string> order = {"right_shoulder", "right_elbow", "left_shoulder",
                                                    "left_elbow", "head_pan"};
            for (unsigned int i = 0; i < robot.dof(); ++i)
            {
                EXPECT_EQ(robot.variableJoint(i).name, order[i]);
                EXPECT_EQ(robot.variableJoint(i).variable, static_cast<int>(i));
            }

            const Joint &head = robot.variableJoint(4);
            EXPECT_EQ(head.type, Joint::Type::Continuous);
            EXPECT_EQ(head.lower, -PI);
            EXPECT_EQ(head.upper, PI);
            EXPECT_LT((robot.variableJoint(3).axis - Eigen::Vector3d(1.0, 1.0, 0.0) / std::sqrt(2.0)).norm(),
                      TOLERANCE);
            EXPECT_EQ(robot.links()[robot.linkIndex("head")].shapes.at(0).shape.radius, 0.12);
        }

        TEST(RobotModel, IsInSubtreeFollowsBranches)
        {
            const RobotModel robot = load("torso_tree.urdf");
            const int torso = robot.linkIndex("torso");
            const int leftUpper = robot.linkIndex("left_upper");
            const int leftHand = robot.linkIndex("left_hand");
            const int rightUpper = robot.linkIndex("right_upper");
            const int rightLower = robot.linkIndex("right_lower");
            const int head = robot.linkIndex("head");

            for (std::size_t link = 0; link < robot.links().size(); ++link)
            {
                EXPECT_TRUE(robot.isInSubtree(static_cast<int>(link), torso));
                EXPECT_TRUE(robot.isInSubtree(static_cast<int>(link), static_cast<int>(link)));
            }
            EXPECT_TRUE(robot.isInSubtree(leftHand, leftUpper));
            EXPECT_TRUE(robot.isInSubtree(rightLower, rightUpper));
            EXPECT_FALSE(robot.isInSubtree(leftUpper, leftHand));
            EXPECT_FALSE(robot.isInSubtree(rightLower, leftUpper));
            EXPECT_FALSE(robot.isInSubtree(leftHand, rightUpper));
            EXPECT_FALSE(robot.isInSubtree(head, leftUpper));
            EXPECT_FALSE(robot.isInSubtree(torso, head));
        }

        TEST(RobotModel, UnknownLinkNameThrowsNamingRobotAndLink)
        {
            const RobotModel robot = load("planar_2link.urdf");
            try
            {
                robot.linkIndex("gripper");
                FAIL() << "no exception";
            }
            catch (const ompl::Exception &e)
            {
                EXPECT_EQ(std::string(e.what()), "robot 'planar_2link' has no link 'gripper'");
            }
        }

        TEST(RobotModel, BadFilesThrowNamingTheFile)
        {
            const std::string missing = ROBOTS_DIR + "no_such_robot.urdf";
            EXPECT_EQ(inputErrorOf([&] { RobotModel::fromUrdfFile(missing); }),
                      missing + ": URDF file not found");
            EXPECT_EQ(inputErrorOf([&] { RobotModel::fromUrdfFile("/dev/zero"); }),
                      "/dev/zero: is not a regular file, not a URDF file");

            const std::string mesh = ROBOTS_DIR + "bad_mesh.urdf";
            // looked for beside the URDF first, then in each folder above it, up to the root
            const std::string message = inputErrorOf([&] { RobotModel::fromUrdfFile(mesh); });
            EXPECT_EQ(
                message.rfind(mesh + ":5: link 'arm': mesh 'arm.stl' not found (looked for " + ROBOTS_DIR +
                                  "arm.stl, " + std::string(OMPL_MM_TEST_DATA_DIR) + "/arm.stl, ",
                              0),
                0u)
                << message;
            EXPECT_NE(message.find(", /arm.stl)"), std::string::npos) << message;
        }

        TEST(RobotModel, BadUrdfTextThrowsNamingSourceAndElement)
        {
            const std::string name = "bad.urdf";
            auto expectError = [&](const std::string &urdf, const std::string &part)
            {
                const std::string message = inputErrorOf([&] { RobotModel::fromUrdfString(urdf, name); });
                EXPECT_EQ(message.rfind(name + ":", 0), 0u) << message;
                EXPECT_NE(message.find(part), std::string::npos) << message;
            };

            expectError("<robot name=\"x\"><link name=\"a\"></robot>", "invalid URDF");
            expectError("<robot name=\"x\"><link name=\"a\"/><link name=\"b\"/></robot>", "invalid URDF");
            expectError(oneJointUrdf("revolute", REVOLUTE_LIMITS, "<mesh filename=\"arm.stl\"/>"),
                        "link 'arm': mesh 'arm.stl' not found");
            expectError(oneJointUrdf("revolute", ""), "joint 'shoulder': revolute joint has no <limit>");
            expectError(oneJointUrdf("prismatic", ""), "joint 'shoulder': prismatic joint has no <limit>");
            expectError(oneJointUrdf("revolute",
                                     "    <limit lower=\"1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>\n"),
                        "joint 'shoulder': lower limit 1 must be below upper limit 1");
            expectError(oneJointUrdf("prismatic",
                                     "    <limit lower=\"2\" upper=\"-1\" effort=\"1\" velocity=\"1\"/>\n"),
                        "joint 'shoulder': lower limit 2 must be below upper limit -1");
            expectError(oneJointUrdf("floating", ""), "joint 'shoulder': floating joints are not supported");
            expectError(oneJointUrdf("planar", ""), "joint 'shoulder': planar joints are not supported");
            expectError(oneJointUrdf("revolute", REVOLUTE_LIMITS + "    <axis xyz=\"0 0 0\"/>\n"),
                        "joint 'shoulder': axis must be a non-zero vector");
            expectError(oneJointUrdf("revolute", REVOLUTE_LIMITS, "<sphere radius=\"-0.1\"/>"),
                        "link 'arm': sphere radius must be positive");
        }

        TEST(RobotModel, ALinkThatLooksSolidMustBeSolid)
        {
            // urdfdom drops a collision whose geometry it cannot read, leaving the link without it
            const std::string dropped = oneJointUrdf("revolute", REVOLUTE_LIMITS, "<sphere radius=\"abc\"/>");
            EXPECT_EQ(inputErrorOf([&] { RobotModel::fromUrdfString(dropped, "bad.urdf"); }),
                      "bad.urdf:4: link 'arm': a <collision> element could not be read (is its geometry "
                      "complete, with numbers where numbers belong?)");
            // a link drawn but not solid
            std::string visualOnly = oneJointUrdf("revolute", REVOLUTE_LIMITS);
            const std::string collision = "<collision>";
            visualOnly.replace(visualOnly.find(collision), collision.size(), "<visual>");
            const std::string collisionEnd = "</collision>";
            visualOnly.replace(visualOnly.find(collisionEnd), collisionEnd.size(), "</visual>");
            EXPECT_EQ(inputErrorOf([&] { RobotModel::fromUrdfString(visualOnly, "bad.urdf"); }),
                      "bad.urdf:4: link 'arm': has <visual> but no <collision> geometry, so it would pass "
                      "through obstacles and objects; add a <collision> element");
            // just inside: a link with neither (a frame, like the base here) is fine
            EXPECT_EQ(
                inputErrorOf(
                    [&]
                    { RobotModel::fromUrdfString(oneJointUrdf("revolute", REVOLUTE_LIMITS), "ok.urdf"); }),
                "");
        }

        TEST(RobotModel, MalformedXmlNamesTheLine)
        {
            // checked before urdfdom sees the text: the line of the unclosed <link>
            const std::string urdf = "<robot name=\"x\">\n  <link name=\"a\">\n</robot>\n";
            const std::string message = inputErrorOf([&] { RobotModel::fromUrdfString(urdf, "bad.urdf"); });
            EXPECT_TRUE(test::startsWith(message, "bad.urdf:2: invalid URDF: malformed XML (")) << message;
        }

        TEST(RobotModel, TextWithoutRobotElementIsRejected)
        {
            // well-formed XML whose root is not <robot>: no line to name, the file only
            EXPECT_EQ(inputErrorOf(
                          [] {
                              RobotModel::fromUrdfString("<robt name=\"x\"><link name=\"a\"/></robt>",
                                                         "bad.urdf");
                          }),
                      "bad.urdf: invalid URDF: no <robot> element");
        }

        TEST(RobotModel, UrdfThatUrdfdomRejectsIsReportedAsInvalid)
        {
            // a robot without a name parses as XML but urdfdom returns no model
            EXPECT_EQ(
                inputErrorOf(
                    [] { RobotModel::fromUrdfString("<robot><link name=\"a\"/></robot>", "bad.urdf"); }),
                "bad.urdf: invalid URDF");
        }

        TEST(RobotModel, NonPositiveCollisionSizesNameTheLinkLineAndValues)
        {
            // the link "arm" is on line 4 of oneJointUrdf(); each size must be > 0, and a tiny one is
            // accepted
            auto error = [](const std::string &geometry)
            {
                return inputErrorOf(
                    [&] {
                        RobotModel::fromUrdfString(oneJointUrdf("revolute", REVOLUTE_LIMITS, geometry),
                                                   "bad.urdf");
                    });
            };
            EXPECT_EQ(error("<box size=\"0.5 0 0.5\"/>"),
                      "bad.urdf:4: link 'arm': box size must be positive, got 0.5 0 0.5");
            EXPECT_EQ(error("<box size=\"-1 0.5 0.5\"/>"),
                      "bad.urdf:4: link 'arm': box size must be positive, got -1 0.5 0.5");
            EXPECT_EQ(error("<box size=\"0.5 1e-06 0.5\"/>"), "");
            EXPECT_EQ(error("<cylinder radius=\"0\" length=\"0.5\"/>"),
                      "bad.urdf:4: link 'arm': cylinder radius and length must be positive, got 0 and 0.5");
            EXPECT_EQ(
                error("<cylinder radius=\"0.1\" length=\"-0.5\"/>"),
                "bad.urdf:4: link 'arm': cylinder radius and length must be positive, got 0.1 and -0.5");
            EXPECT_EQ(error("<cylinder radius=\"1e-06\" length=\"1e-06\"/>"), "");
            EXPECT_EQ(error("<sphere radius=\"0\"/>"),
                      "bad.urdf:4: link 'arm': sphere radius must be positive, got 0");
            EXPECT_EQ(error("<sphere radius=\"-0.1\"/>"),
                      "bad.urdf:4: link 'arm': sphere radius must be positive, got -0.1");
            EXPECT_EQ(error("<sphere radius=\"1e-06\"/>"), "");
        }

        TEST(RobotModel, LimitsJustApartAndTinyAxesAreAccepted)
        {
            // the bounds of the joint checks: lower just below upper, any non-zero axis (normalised)
            const RobotModel robot = RobotModel::fromUrdfString(
                oneJointUrdf("prismatic",
                             "    <axis xyz=\"0 1e-9 0\"/>\n"
                             "    <limit lower=\"1\" upper=\"1.000001\" effort=\"1\" velocity=\"1\"/>\n"),
                "ok.urdf");
            ASSERT_EQ(robot.dof(), 1u);
            EXPECT_EQ(robot.variableJoint(0).lower, 1.0);
            EXPECT_EQ(robot.variableJoint(0).upper, 1.000001);
            EXPECT_LT((robot.variableJoint(0).axis - Eigen::Vector3d::UnitY()).norm(), TOLERANCE);
        }

        TEST(RobotModel, LinkIndexOutOfRangeThrows)
        {
            // link indices of isInSubtree() and linkFrame() must lie in [0, links)
            const RobotModel robot = load("planar_2link.urdf");
            const double q[] = {0.0, 0.0};
            const int last = static_cast<int>(robot.links().size()) - 1;
            auto message = [](auto &&f) -> std::string
            {
                try
                {
                    f();
                }
                catch (const ompl::Exception &e)
                {
                    return e.what();
                }
                return "";
            };
            EXPECT_EQ(message([&] { robot.linkFrame(q, Eigen::Isometry3d::Identity(), last + 1); }),
                      "RobotModel: link index 4 out of range [0, 4)");
            EXPECT_EQ(message([&] { robot.isInSubtree(-1, 0); }),
                      "RobotModel: link index -1 out of range [0, 4)");
            EXPECT_EQ(message([&] { robot.isInSubtree(0, last + 1); }),
                      "RobotModel: link index 4 out of range [0, 4)");
            EXPECT_EQ(message([&] { robot.linkFrame(q, Eigen::Isometry3d::Identity(), last); }), "");
            EXPECT_TRUE(robot.isInSubtree(last, 0));
        }

        TEST(RobotModel, JointErrorsGiveTheLineOfTheJoint)
        {
            const std::string urdf = oneJointUrdf("revolute", "");
            const std::string before = urdf.substr(0, urdf.find("<joint"));
            const long line = 1 + std::count(before.begin(), before.end(), '\n');
            EXPECT_EQ(
                inputErrorOf([&] { RobotModel::fromUrdfString(urdf, "arm.urdf"); }),
                "arm.urdf:" + std::to_string(line) + ": joint 'shoulder': revolute joint has no <limit>");
        }

        TEST(RobotModel, JointsThatDoNotFormATreeAreErrorsAtTheJointThatBreaksIt)
        {
            // base -> arm -> hand, then one more joint (urdfdom would leave such a graph a cycle of
            // shared pointers, never freed)
            const auto urdfWith = [](const std::string &parent, const std::string &child)
            {
                return "<robot name=\"tree\">\n"
                       "  <link name=\"base\"/>\n"
                       "  <link name=\"arm\"/>\n"
                       "  <link name=\"hand\"/>\n"
                       "  <joint name=\"shoulder\" type=\"fixed\"><parent link=\"base\"/><child "
                       "link=\"arm\"/></joint>\n"
                       "  <joint name=\"wrist\" type=\"fixed\"><parent link=\"arm\"/><child "
                       "link=\"hand\"/></joint>\n"
                       "  <joint name=\"extra\" type=\"fixed\"><parent link=\"" +
                       parent + "\"/><child link=\"" + child +
                       "\"/></joint>\n"
                       "</robot>\n";
            };
            const auto error = [&](const std::string &parent, const std::string &child) {
                return inputErrorOf([&]
                                    { RobotModel::fromUrdfString(urdfWith(parent, child), "tree.urdf"); });
            };
            EXPECT_EQ(error("base", "hand"),
                      "tree.urdf:7: joint 'extra': link 'hand' is already the child of "
                      "joint 'wrist': the links must form a tree");
            EXPECT_EQ(error("hand", "base"),
                      "tree.urdf:7: joint 'extra': closes a loop: its child link 'base' is "
                      "its parent link 'hand' or above it");
            EXPECT_EQ(error("hand", "hand"),
                      "tree.urdf:7: joint 'extra': link 'hand' is already the child of "
                      "joint 'wrist': the links must form a tree");
            // a link that is its own parent, with no other parent
            const std::string self =
                "<robot name=\"self\">\n  <link name=\"base\"/>\n  <link name=\"a\"/>\n"
                "  <joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"a\"/></joint>\n"
                "</robot>\n";
            EXPECT_EQ(inputErrorOf([&] { RobotModel::fromUrdfString(self, "self.urdf"); }),
                      "self.urdf:4: joint 'j': closes a loop: its child link 'a' is its parent link 'a' or "
                      "above it");
        }

        TEST(RobotModel, ABareAmpersandIsMalformedXmlAtItsLineButNotInACommentOrCdata)
        {
            // urdfdom leaks the model it was building when it meets one
            const std::string urdf = oneJointUrdf("revolute", REVOLUTE_LIMITS);
            std::string bare = urdf;
            bare.replace(bare.find("\"arm\"/>"), 7, "\"a&rm\"/>");  // the joint's child, line 11
            EXPECT_EQ(inputErrorOf([&] { RobotModel::fromUrdfString(bare, "amp.urdf"); }),
                      "amp.urdf:11: invalid URDF: malformed XML (a '&' that starts no entity reference; "
                      "write &amp;)");
            // escaped, or in a comment or CDATA section, it is XML (the escaped name then matches no link)
            std::string commented = urdf;
            commented.replace(commented.find("<robot"), 0, "<!-- Jentzsch & Gaschler -->");
            commented.replace(commented.find("<link name=\"base\"/>"), 0, "<![CDATA[a & b]]>");
            EXPECT_EQ(inputErrorOf([&] { RobotModel::fromUrdfString(commented, "amp.urdf"); }), "");
            std::string escaped = bare;
            escaped.replace(escaped.find("a&rm"), 4, "a&amp;rm&#65;&#x41;");
            EXPECT_FALSE(ompl_core::test::contains(
                inputErrorOf([&] { RobotModel::fromUrdfString(escaped, "amp.urdf"); }), "'&'"));
        }

        TEST(RobotModel, SceneMobileDiscHasTwoPrismaticJointsAndASphere)
        {
            const RobotModel robot =
                RobotModel::fromUrdfFile(std::string(OMPL_MM_SCENES_DIR) + "/robots/mobile_disc.urdf");
            EXPECT_EQ(robot.links()[0].name, "world");
            ASSERT_EQ(robot.dof(), 2u);
            EXPECT_EQ(robot.variableJoint(0).name, "x");
            EXPECT_EQ(robot.variableJoint(1).name, "y");
            for (unsigned int i = 0; i < 2; ++i)
            {
                EXPECT_EQ(robot.variableJoint(i).type, Joint::Type::Prismatic);
                EXPECT_EQ(robot.variableJoint(i).lower, -2.5);
                EXPECT_EQ(robot.variableJoint(i).upper, 2.5);
            }
            const Link &body = robot.links()[robot.linkIndex("body")];
            ASSERT_EQ(body.shapes.size(), 1u);
            EXPECT_EQ(body.shapes[0].shape.kind, Shape::Kind::Sphere);
            EXPECT_EQ(body.shapes[0].shape.radius, 0.2);
            EXPECT_LT((body.shapes[0].origin.translation() - Eigen::Vector3d(0.0, 0.0, 0.25)).norm(),
                      TOLERANCE);

            // the sphere centre in the world sits at (x, y, 0.25)
            const double q[] = {1.25, -0.75};
            const Eigen::Vector3d centre =
                robot.linkFrame(q, Eigen::Isometry3d::Identity(), robot.linkIndex("body")) *
                body.shapes[0].origin.translation();
            EXPECT_LT((centre - Eigen::Vector3d(1.25, -0.75, 0.25)).norm(), TOLERANCE);
        }

        /** A link frame computed joint by joint from the URDF's numbers (origins, axes, mimic
            factors written out here), independent of RobotModel's tree. */
        Eigen::Isometry3d mimicGripperFrame(const std::string &link, double wrist, double finger)
        {
            const auto pose = [](double x, double y, double z)
            { return Eigen::Isometry3d(Eigen::Translation3d(x, y, z)); };
            const Eigen::Isometry3d hand = pose(0, 0, 0.3) *
                                           Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()) *
                                           Eigen::AngleAxisd(wrist, Eigen::Vector3d::UnitZ());
            if (link == "right_finger")
                return hand * pose(0, -0.01, 0.05) * pose(0, -finger, 0);
            const Eigen::Isometry3d left = hand * pose(0, 0.01, 0.05) * pose(0, finger, 0);
            const double knuckle = 2.0 * finger + 0.1;
            const Eigen::Isometry3d knuckleFrame =
                left * pose(0, 0, 0.03) * Eigen::AngleAxisd(knuckle, Eigen::Vector3d::UnitX());
            if (link == "knuckle")
                return knuckleFrame;
            return knuckleFrame * pose(0, 0, 0.02) *
                   Eigen::AngleAxisd(-0.5 * knuckle, Eigen::Vector3d::UnitX());
        }

        TEST(RobotModel, MimicJointsFollowTheirLeaderAndAddNoVariable)
        {
            const RobotModel robot = load("mimic_gripper.urdf");
            ASSERT_EQ(robot.dof(), 2u);
            EXPECT_EQ(robot.variableNames(), "wrist, left_finger_joint");
            EXPECT_EQ(robot.variableJoint(0).type, Joint::Type::Continuous);
            const Joint &tip = robot.joints()[robot.links()[robot.linkIndex("tip")].joint];
            EXPECT_EQ(robot.joints()[tip.mimics].name, "left_finger_joint");  // the first leader
            EXPECT_DOUBLE_EQ(tip.multiplier, -1.0);
            EXPECT_DOUBLE_EQ(tip.offset, -0.05);
            std::mt19937 rng(5);
            for (int trial = 0; trial < 20; ++trial)
            {
                const std::vector<double> q = randomJoints(robot, rng);
                std::vector<Eigen::Isometry3d> frames;
                robot.forwardKinematics(q.data(), Eigen::Isometry3d::Identity(), frames);
                for (const char *link : {"right_finger", "knuckle", "tip"})
                {
                    const Eigen::Isometry3d expected = mimicGripperFrame(link, q[0], q[1]);
                    EXPECT_LT(maxDifference(frames[robot.linkIndex(link)], expected), 1e-12) << link;
                    EXPECT_LT(maxDifference(robot.linkFrame(q.data(), Eigen::Isometry3d::Identity(),
                                                            robot.linkIndex(link)),
                                            expected),
                              1e-12)
                        << link;
                }
            }
        }

        TEST(RobotModel, BadMimicsNameTheJointAndLine)
        {
            std::string urdf;
            ompl_core::readInputFile(ROBOTS_DIR + "mimic_gripper.urdf", "URDF file").swap(urdf);
            const auto lineOf = [&urdf](const std::string &text)
            {
                const std::string before = urdf.substr(0, urdf.find(text));
                return std::to_string(1 + std::count(before.begin(), before.end(), '\n'));
            };
            const auto replaced = [&urdf](const std::string &from, const std::string &to)
            {
                std::string changed = urdf;
                changed.replace(changed.find(from), from.size(), to);
                return changed;
            };
            const std::string right = lineOf("<joint name=\"right_finger_joint\"");
            EXPECT_EQ(inputErrorOf(
                          [&]
                          {
                              RobotModel::fromUrdfString(replaced("<mimic joint=\"left_finger_joint\"/>",
                                                                  "<mimic joint=\"thumb\"/>"),
                                                         "g.urdf");
                          }),
                      "g.urdf:" + right +
                          ": joint 'right_finger_joint': <mimic> names joint 'thumb', which the "
                          "robot does not have");
            const std::string fixedWrist = replaced("<joint name=\"wrist\" type=\"continuous\">",
                                                    "<joint name=\"wrist\" type=\"fixed\">");
            EXPECT_EQ(inputErrorOf(
                          [&]
                          {
                              RobotModel::fromUrdfString(
                                  [&]
                                  {
                                      std::string text = fixedWrist;
                                      const std::string from = "<mimic joint=\"left_finger_joint\"/>";
                                      text.replace(text.find(from), from.size(), "<mimic joint=\"wrist\"/>");
                                      return text;
                                  }(),
                                  "g.urdf");
                          }),
                      "g.urdf:" + right +
                          ": joint 'right_finger_joint': <mimic> follows joint 'wrist', which "
                          "is fixed");
            // the left finger following the tip closes a cycle: left -> tip -> knuckle -> left
            const std::string cycle =
                replaced("<limit lower=\"0\" upper=\"0.04\" effort=\"10\" velocity=\"0.1\"/>\n  </joint>",
                         "<limit lower=\"0\" upper=\"0.04\" effort=\"10\" velocity=\"0.1\"/>\n"
                         "    <mimic joint=\"tip_joint\"/>\n  </joint>");
            const std::string message = inputErrorOf([&] { RobotModel::fromUrdfString(cycle, "g.urdf"); });
            EXPECT_NE(message.find("follow each other in a cycle"), std::string::npos) << message;
            EXPECT_EQ(message.rfind("g.urdf:", 0), 0u) << message;
        }

        TEST(RobotModel, FixedJointsKeepTheirFramesAndLeaveTheOthersInOrder)
        {
            const RobotModel robot = load("mimic_gripper.urdf");
            const RobotModel held = robot.withJointsFixed({{"left_finger_joint", 0.03}});
            ASSERT_EQ(held.dof(), 1u);
            EXPECT_EQ(held.variableNames(), "wrist");
            for (const Joint &joint : held.joints())
                EXPECT_TRUE(joint.mimics < 0 && (joint.type == Joint::Type::Fixed) == (joint.name != "wrist"))
                    << joint.name;
            std::vector<Eigen::Isometry3d> full, fixed;
            for (const double wrist : {-2.0, 0.0, 2.5})
            {
                const double q[] = {wrist, 0.03};
                robot.forwardKinematics(q, someBase(), full);
                held.forwardKinematics(q, someBase(), fixed);
                for (std::size_t l = 0; l < full.size(); ++l)
                    EXPECT_LT(maxDifference(full[l], fixed[l]), 1e-12) << robot.links()[l].name;
            }
            EXPECT_EQ(inputErrorOf(
                          [&] {
                              robot.withJointsFixed({{"thumb", 0.0}});
                          }),
                      "robot 'mimic_gripper' has no moving joint 'thumb' (its moving joints: wrist, "
                      "left_finger_joint)");
            EXPECT_EQ(inputErrorOf(
                          [&] {
                              robot.withJointsFixed({{"knuckle_joint", 0.0}});
                          }),
                      "joint 'knuckle_joint' follows joint 'left_finger_joint' (<mimic>); fix that one");
            EXPECT_EQ(inputErrorOf(
                          [&] {
                              robot.withJointsFixed({{"left_finger_joint", 0.05}});
                          }),
                      "joint 'left_finger_joint': value 0.05 lies outside its limits [0, 0.04]");
            EXPECT_EQ(
                inputErrorOf(
                    [&] {
                        held.withJointsFixed({{"left_finger_joint", 0.01}});
                    }),
                "robot 'mimic_gripper' has no moving joint 'left_finger_joint' (its moving joints: wrist)");
        }
    }  // namespace
}  // namespace ompl_mm
