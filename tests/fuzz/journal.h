// A journal of the calls that changed a world, one line each, and its replay. The fuzz driver
// makes its changing calls through a Journal, so that when a world goes wrong the calls that
// built it can be written out, replayed, and cut down (tests/fuzz/reduce.py) to a short
// reproduction. Refused calls change nothing (the driver checks that), so only accepted ones
// are written. Objects are named by kind and creation number (b3, s7, j2, m0); a replayed line
// naming an object whose creating line was cut is skipped. A step line may end with a repeat
// count, for reproductions written by hand.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "pivot/pivot.h"

namespace pivot::fuzz {

/// The fuzz's pre-solve and custom-filter callbacks (or none): fixed functions of their
/// arguments that also check the world refuses changes from inside them.
void installFuzzCallbacks(World& world, bool preSolve, bool customFilter);

class Journal {
public:
    /// Starts a new journal for `world`, made from `def`.
    void begin(World& world, const WorldDef& def);
    const std::vector<std::string>& lines() const { return lines_; }
    /// Writes the journal to a file; false if it cannot.
    bool write(const std::string& path) const;

    // The world's changing calls: each makes the call and, if it returns, writes its line.
    BodyId createBody(const BodyDef& def);
    ShapeId createShape(BodyId body, const ShapeDef& def, const Circle& circle);
    ShapeId createShape(BodyId body, const ShapeDef& def, const Polygon& polygon);
    ShapeId createShape(BodyId body, const ShapeDef& def, const Segment& segment);
    ShapeId createShape(BodyId body, const ShapeDef& def, const ChainSegment& segment);
    ShapeId createShape(BodyId body, const ShapeDef& def, const Capsule& capsule);
    std::vector<ShapeId> createChain(BodyId body, const ShapeDef& def, const Chain& chain);
    JointId createJoint(const RevoluteJointDef& def);
    JointId createJoint(const DistanceJointDef& def);
    JointId createJoint(const PulleyJointDef& def);
    JointId createJoint(const GearJointDef& def);
    JointId createJoint(const PrismaticJointDef& def);
    JointId createJoint(const WeldJointDef& def);
    JointId createJoint(const WheelJointDef& def);
    JointId createJoint(const FrictionJointDef& def);
    JointId createJoint(const MotorJointDef& def);
    MouseJointId createMouseJoint(const MouseJointDef& def);
    void destroyBody(BodyId id);
    void destroyShape(ShapeId id);
    void destroyJoint(JointId id);
    void destroyMouseJoint(MouseJointId id);
    void setBodyTransform(BodyId id, Vec2 position, float angle);
    void setBodyLinearVelocity(BodyId id, Vec2 v);
    void setBodyAngularVelocity(BodyId id, float w);
    void applyForce(BodyId id, Vec2 force, Vec2 point);
    void applyForceToCenter(BodyId id, Vec2 force);
    void applyTorque(BodyId id, float torque);
    void applyLinearImpulse(BodyId id, Vec2 impulse, Vec2 point);
    void applyAngularImpulse(BodyId id, float impulse);
    void setBodyAwake(BodyId id, bool awake);
    void setBodySleepAllowed(BodyId id, bool allowed);
    void setBodyBullet(BodyId id, bool bullet);
    void setBodyContinuous(BodyId id, bool continuous);
    void setBodyType(BodyId id, BodyType type);
    void setShapeDensity(ShapeId id, float density);
    void setShapeSensor(ShapeId id, bool sensor);
    void setShapeFriction(ShapeId id, float friction);
    void setShapeRestitution(ShapeId id, float restitution);
    void setBodyFixedRotation(BodyId id, bool fixedRotation);
    void setBodyLinearDamping(BodyId id, float damping);
    void setBodyAngularDamping(BodyId id, float damping);
    void setBodyGravityScale(BodyId id, float scale);
    void setShapeFilter(ShapeId id, const Filter& filter);
    void setJointLimit(JointId id, const JointLimit& limit);
    void setDistanceJointRestLength(JointId id, float length);
    void setDistanceJointLimit(JointId id, const LengthLimit& limit);
    void setDistanceJointSpring(JointId id, const JointSpring& spring);
    void setPrismaticJointLimit(JointId id, const TranslationLimit& limit);
    void setPrismaticJointMotor(JointId id, const LinearMotor& motor);
    void setPrismaticJointSpring(JointId id, const JointSpring& spring);
    void setWeldJointLinearSpring(JointId id, const JointSpring& spring);
    void setWheelJointSpring(JointId id, const JointSpring& spring);
    void setGearJointRatio(JointId id, float ratio);
    void setWheelJointLimit(JointId id, const TranslationLimit& limit);
    void setWeldJointAngularSpring(JointId id, const JointSpring& spring);
    void setJointMaxForce(JointId id, float force);
    void setMotorJointLinearOffset(JointId id, Vec2 offset);
    void setMotorJointCorrectionFactor(JointId id, float factor);
    void setJointMotor(JointId id, const JointMotor& motor);
    void setJointPositionSolver(JointId id, PositionSolver solver);
    void setJointBiasFactor(JointId id, std::optional<float> bias);
    void setJointExtraPositionIterations(JointId id, int count);
    void setJointSoftness(JointId id, const JointSoftness& softness);
    void setJointLetGoSeparation(JointId id, std::optional<float> separation);
    void rearmJoint(JointId id);
    void setBodyUserData(BodyId id, std::uint64_t value);
    void setShapeUserData(ShapeId id, std::uint64_t value);
    void setJointUserData(JointId id, std::uint64_t value);
    void setMouseTarget(MouseJointId id, Vec2 target);
    void setGravity(Vec2 gravity);
    void setContactCorrection(ContactCorrection correction);
    void setSubstepCount(int count);
    void setSleepEnabled(bool enabled);
    void setContinuousEnabled(bool enabled);
    void setContinuousCollision(ContinuousCollision policy);
    void setHitEventThreshold(float speed);
    void setShapeHitEvents(ShapeId id, bool enabled);
    void setShapePreSolve(ShapeId id, bool enabled);
    void setJointBreakForce(JointId id, float force);
    void setJointBreakTorque(JointId id, float torque);
    void setJointCollideConnected(JointId id, bool collide);
    /// Installs (or removes) the fuzz's fixed pre-solve and custom-filter callbacks
    /// (installFuzzCallbacks), so a journal replays them.
    void setCallbacks(bool preSolve, bool customFilter);
    void step(float dt, int velocityIterations, int positionIterations);

private:
    using Key = std::tuple<char, std::int32_t, std::uint32_t>;
    template <typename Id>
    std::string nameOf(char kind, Id id);
    template <typename Id>
    std::string nameNew(char kind, Id id);

    World* world_ = nullptr;
    std::vector<std::string> lines_;
    std::map<Key, std::string> names_;
    int created_ = 0;
};

struct ReplayResult {
    int lines = 0;
    int applied = 0;  ///< calls that returned
    int refused = 0;  ///< calls that threw pivot::Error
    int skipped = 0;  ///< lines naming an object that does not exist (its creation was cut)
    /// The first line (1-based) after whose step a body or joint reported a non-finite number.
    int nonFiniteLine = 0;
    std::string nonFinite;  ///< what was not finite
    /// The first line after whose step a body's state was beyond the input limits (one the
    /// API would refuse to be given back), and which.
    int beyondLimitsLine = 0;
    std::string beyondLimits;
    /// Joints the world reported let go, and body-steps whose non-finite solved state it
    /// discarded (StepStats), over the whole replay.
    long letGoJoints = 0;
    long discardedBodies = 0;
    std::string error;  ///< a line that could not be read
};

/// Replays a journal into a fresh world, stopping at the first non-finite number or state
/// beyond the input limits.
ReplayResult replay(std::istream& in);

/// Whether every body and joint of the world reports finite numbers; if not, what did not.
bool worldIsFinite(const World& world, std::string* what = nullptr);
/// Whether every body's position, angle and velocities are within the input limits, so that
/// the API would take them back; if not, which body.
bool worldWithinLimits(const World& world, std::string* what = nullptr);

}  // namespace pivot::fuzz
