// World::stateHash: what a determinism check and the "a refused call changes nothing" checks
// compare.
#include "core/state_hash.h"
#include "world/world_impl.h"

namespace pivot {

namespace {
void hashJointData(StateHasher& h, const RevoluteJoint& j) {
    h.add(j.enableLimit);
    h.add(j.lowerAngle);
    h.add(j.upperAngle);
    h.add(j.enableMotor);
    h.add(j.motorSpeed);
    h.add(j.maxMotorTorque);
    h.add(j.impulse);
    h.add(j.motorImpulse);
    h.add(j.lowerImpulse);
    h.add(j.upperImpulse);
}
void hashJointData(StateHasher& h, const DistanceJoint& j) {
    // The type first (a revolute joint's data goes in without it, so that worlds of revolute
    // joints keep the hashes recorded before there were other types).
    h.add(static_cast<std::int32_t>(JointType::Distance));
    h.add(j.length);
    h.add(j.enableLimit);
    h.add(j.minLength);
    h.add(j.maxLength);
    h.add(j.enableSpring);
    h.add(j.hertz);
    h.add(j.dampingRatio);
    h.add(j.impulse);
    h.add(j.lowerImpulse);
    h.add(j.upperImpulse);
    h.add(j.axis);
}
void hashJointData(StateHasher& h, const PulleyJoint& j) {
    h.add(static_cast<std::int32_t>(JointType::Pulley));
    h.add(j.groundAnchorA);
    h.add(j.groundAnchorB);
    h.add(j.lengthA);
    h.add(j.lengthB);
    h.add(j.ratio);
    h.add(j.impulse);
    h.add(j.axisB);
}
void hashJointData(StateHasher& h, const FrictionJoint& j) {
    h.add(static_cast<std::int32_t>(JointType::Friction));
    h.add(j.maxForce);
    h.add(j.maxTorque);
    h.add(j.linearImpulse);
    h.add(j.angularImpulse);
}
void hashJointData(StateHasher& h, const MotorJoint& j) {
    h.add(static_cast<std::int32_t>(JointType::Motor));
    h.add(j.linearOffset);
    h.add(j.angularOffset);
    h.add(j.maxForce);
    h.add(j.maxTorque);
    h.add(j.correctionFactor);
    h.add(j.linearImpulse);
    h.add(j.angularImpulse);
}
void hashJointData(StateHasher& h, const WeldJoint& j) {
    h.add(static_cast<std::int32_t>(JointType::Weld));
    for (const JointSpring& s : {j.linearSpring, j.angularSpring}) {
        h.add(s.enabled);
        h.add(s.hertz);
        h.add(s.dampingRatio);
    }
    h.add(j.impulse.x);
    h.add(j.impulse.y);
    h.add(j.impulse.z);
}
void hashJointData(StateHasher& h, const WheelJoint& j) {
    h.add(static_cast<std::int32_t>(JointType::Wheel));
    h.add(j.localAxisA);
    h.add(j.spring.enabled);
    h.add(j.spring.hertz);
    h.add(j.spring.dampingRatio);
    h.add(j.enableLimit);
    h.add(j.lowerTranslation);
    h.add(j.upperTranslation);
    h.add(j.enableMotor);
    h.add(j.motorSpeed);
    h.add(j.maxMotorTorque);
    h.add(j.impulse);
    h.add(j.springImpulse);
    h.add(j.lowerImpulse);
    h.add(j.upperImpulse);
    h.add(j.motorImpulse);
    h.add(j.axis);
}
void hashJointData(StateHasher& h, const PrismaticJoint& j) {
    h.add(static_cast<std::int32_t>(JointType::Prismatic));
    h.add(j.localAxisA);
    h.add(j.enableLimit);
    h.add(j.lowerTranslation);
    h.add(j.upperTranslation);
    h.add(j.enableMotor);
    h.add(j.motorSpeed);
    h.add(j.maxMotorForce);
    h.add(j.enableSpring);
    h.add(j.hertz);
    h.add(j.dampingRatio);
    h.add(j.impulse);
    h.add(j.motorImpulse);
    h.add(j.lowerImpulse);
    h.add(j.upperImpulse);
    h.add(j.springImpulse);
    h.add(j.axis);
}
void hashGearSide(StateHasher& h, const GearSide& s) {
    h.add(s.prismatic);
    h.add(s.joint);
    h.add(s.base);
    h.add(s.localAnchorBase);
    h.add(s.localAnchorMover);
    h.add(s.localAxis);
    h.add(s.referenceAngle);
}
void hashJointData(StateHasher& h, const GearJoint& j) {
    h.add(static_cast<std::int32_t>(JointType::Gear));
    hashGearSide(h, j.side1);
    hashGearSide(h, j.side2);
    h.add(j.ratio);
    h.add(j.constant);
    h.add(j.impulse);
    h.add(j.linearB);
    h.add(j.angularB);
}
}  // namespace

// Everything a public call can change goes in, so that "the hash is unchanged" means "the world
// is unchanged": settings, every field of every object (derived ones too, such as the inverse
// mass, so that a forgotten recomputation shows), the list links, the broad phase's boxes, the
// contacts with their manifolds, and what the last step reported. Only scratch buffers that
// every step rebuilds are left out.
std::uint64_t World::stateHash() const {
    impl_->requireRead("World::stateHash");
    const Impl& w = *impl_;
    StateHasher h;
    h.add(w.settings.gravity);
    h.add(static_cast<std::int32_t>(w.settings.defaultPositionSolver));
    h.add(w.settings.warmStarting);
    h.add(static_cast<std::int32_t>(w.settings.contactCorrection));
    h.add(w.settings.contactBiasFactor);
    h.add(w.settings.restitutionThreshold);
    h.add(w.settings.enableSleep);
    h.add(w.settings.enableContinuous);
    h.add(w.settings.jointLetGoSeparation);
    // These, and the soft-step settings, are hashed only when they differ from their defaults,
    // so that hashes recorded before they existed still hold.
    if (w.settings.substepCount != 1) h.add(w.settings.substepCount);
    if (w.contactManager.broadPhase().boxes() != BroadPhaseBoxes::Predictive) {
        h.add(static_cast<std::int32_t>(w.contactManager.broadPhase().boxes()));
    }
    if (w.settings.hitEventThreshold != kDefaultHitEventThreshold) h.add(w.settings.hitEventThreshold);
    if (w.settings.continuousCollision != ContinuousCollision::Substeps) {
        h.add(static_cast<std::int32_t>(w.settings.continuousCollision));
    }
    if (w.settings.contactHertz != kDefaultContactHertz ||
        w.settings.contactDampingRatio != kDefaultContactDampingRatio ||
        w.settings.contactPushSpeed != kDefaultContactPushSpeed) {
        h.add(w.settings.contactHertz);
        h.add(w.settings.contactDampingRatio);
        h.add(w.settings.contactPushSpeed);
    }
    h.add(w.previousInvDt);
    h.add(w.contactManager.hasNewShapes());

    h.add(w.bodies.size());
    w.bodies.forEach([&](std::int32_t index, const Body& b) {
        h.add(index);
        h.add(static_cast<std::int32_t>(w.bodies.generation(index)));
        h.add(static_cast<std::int32_t>(b.type));
        h.add(b.xf);
        h.add(b.localCenter);
        h.add(b.center);
        h.add(b.angle);
        h.add(b.linearVelocity);
        h.add(b.angularVelocity);
        h.add(b.force);
        h.add(b.torque);
        h.add(b.mass);
        h.add(b.invMass);
        h.add(b.inertia);
        h.add(b.invInertia);
        h.add(b.linearDamping);
        h.add(b.angularDamping);
        h.add(b.gravityScale);
        h.add(b.fixedRotation);
        h.add(b.userData);
        h.add(b.shapeList);
        h.add(b.jointList);
        h.add(b.contactList);
        h.add(b.mouseList);
        h.add(b.shapeCount);
        h.add(b.awake);
        h.add(b.allowSleep);
        h.add(b.sleepTime);
        h.add(b.center0);
        h.add(b.angle0);
        h.add(b.bullet);
        h.add(b.continuous);
    });
    h.add(w.shapes.size());
    w.shapes.forEach([&](std::int32_t index, const Shape& s) {
        h.add(index);
        h.add(static_cast<std::int32_t>(w.shapes.generation(index)));
        h.add(s.body);
        h.add(static_cast<std::int32_t>(s.type));
        if (s.type == ShapeType::Circle) {
            h.add(s.circle.center);
            h.add(s.circle.radius);
        } else {
            h.add(s.polygon.count);
            for (int i = 0; i < s.polygon.count; ++i) h.add(s.polygon.vertices[i]);
            // Only when rounded, so that hashes recorded before rounding existed still hold.
            if (s.polygon.radius != 0.0f) h.add(s.polygon.radius);
            if (s.type == ShapeType::ChainSegment) {
                h.add(s.ghost1);
                h.add(s.ghost2);
            }
        }
        h.add(s.density);
        h.add(s.friction);
        h.add(s.restitution);
        h.add(static_cast<std::int32_t>(s.filter.categoryBits | (s.filter.maskBits << 16)));
        h.add(static_cast<std::int32_t>(s.filter.groupIndex));
        h.add(s.userData);
        if (s.sensor) h.add(s.sensor);
        if (s.hitEvents) h.add(std::int32_t{101});
        if (s.preSolve) h.add(std::int32_t{102});
        h.add(s.prev);
        h.add(s.next);
        const AABB& box = w.contactManager.broadPhase().fatBox(s.proxyId);
        h.add(box.lower);
        h.add(box.upper);
    });
    h.add(w.joints.size());
    w.joints.forEach([&](std::int32_t index, const Joint& j) {
        h.add(index);
        h.add(static_cast<std::int32_t>(w.joints.generation(index)));
        for (const BodyEdge& e : j.edges) {
            h.add(e.body);
            h.add(e.prevKey);
            h.add(e.nextKey);
        }
        h.add(j.localAnchorA);
        h.add(j.localAnchorB);
        h.add(j.referenceAngle);
        h.add(static_cast<std::int32_t>(j.solver));
        h.add(j.hasBiasOverride);
        h.add(j.biasOverride);
        if (j.softness != JointSoftness{}) {
            h.add(j.softness.hertz);
            h.add(j.softness.dampingRatio);
            h.add(j.softness.compliance);
        }
        h.add(j.collideConnected);
        h.add(j.userData);
        std::visit([&](const auto& data) { hashJointData(h, data); }, j.data);
        h.add(j.impulseInvDt);
        h.add(j.letGo);
        h.add(static_cast<std::int32_t>(j.letGoReason));
        h.add(j.letGoAt);
        h.add(j.hasLetGoOverride);
        h.add(j.letGoOverride);
        // Only when a gear is built on the joint, so that worlds without gears keep the hashes
        // recorded before there were any.
        if (j.gearCount != 0) h.add(j.gearCount);
        // Likewise only when set: the break thresholds and what broke a joint.
        if (j.breakForce != 0.0f || j.breakTorque != 0.0f) {
            h.add(j.breakForce);
            h.add(j.breakTorque);
        }
        if (j.letGoReaction != 0.0f) h.add(j.letGoReaction);
    });
    h.add(w.mouseJoints.size());
    w.mouseJoints.forEach([&](std::int32_t index, const MouseJoint& m) {
        h.add(index);
        h.add(static_cast<std::int32_t>(w.mouseJoints.generation(index)));
        h.add(m.body);
        h.add(m.next);
        h.add(m.localAnchor);
        h.add(m.target);
        h.add(m.maxForce);
        h.add(m.hertz);
        h.add(m.dampingRatio);
        h.add(m.impulse);
    });
    h.add(w.contacts.size());
    w.contacts.forEach([&](std::int32_t index, const Contact& c) {
        h.add(index);
        for (const BodyEdge& e : c.edges) {
            h.add(e.body);
            h.add(e.prevKey);
            h.add(e.nextKey);
        }
        h.add(c.shapeA);
        h.add(c.shapeB);
        h.add(c.friction);
        h.add(c.restitution);
        h.add(c.touching);
        if (c.sensor) h.add(c.sensor);  // only then, so hashes recorded before sensors hold
        if (!c.enabled) h.add(std::int32_t{103});  // the pre-solve callback's answer
        h.add(c.needsFiltering);
        h.add(c.serial);
        const Manifold& m = c.manifold;
        h.add(static_cast<std::int32_t>(m.type));
        h.add(m.localNormal);
        h.add(m.localPoint);
        h.add(m.pointCount);
        for (int i = 0; i < m.pointCount; ++i) {
            h.add(m.points[i].localPoint);
            h.add(m.points[i].normalImpulse);
            h.add(m.points[i].tangentImpulse);
            h.add(static_cast<std::int32_t>(m.points[i].id));
            // What a hit event reads, for the contacts that report hits.
            if (w.shapes[c.shapeA].hitEvents || w.shapes[c.shapeB].hitEvents) {
                h.add(m.points[i].approachSpeed);
            }
        }
    });
    // Sensor and hit events, when there are any (recorded hashes predate them).
    for (const std::vector<SensorEvent>* events :
         {&w.contactManager.sensorBeginEvents(), &w.contactManager.sensorEndEvents()}) {
        if (events->empty()) continue;
        h.add(static_cast<std::int32_t>(events->size()));
        for (const SensorEvent& e : *events) {
            h.add(e.sensor.index);
            h.add(static_cast<std::int32_t>(e.sensor.generation));
            h.add(e.visitor.index);
            h.add(static_cast<std::int32_t>(e.visitor.generation));
        }
    }
    if (!w.hitEvents.empty()) {
        h.add(static_cast<std::int32_t>(w.hitEvents.size()));
        for (const ContactHitEvent& e : w.hitEvents) {
            h.add(e.shapeA.index);
            h.add(e.shapeB.index);
            h.add(e.point);
            h.add(e.normal);
            h.add(e.approachSpeed);
        }
    }
    for (const std::vector<ContactEvent>* events :
         {&w.contactManager.beginEvents(), &w.contactManager.endEvents()}) {
        h.add(static_cast<std::int32_t>(events->size()));
        for (const ContactEvent& e : *events) {
            h.add(e.shapeA.index);
            h.add(static_cast<std::int32_t>(e.shapeA.generation));
            h.add(e.shapeB.index);
            h.add(static_cast<std::int32_t>(e.shapeB.generation));
        }
    }
    h.add(static_cast<std::int32_t>(w.letGoEvents.size()));
    for (const JointLetGoEvent& e : w.letGoEvents) {
        h.add(e.joint.index);
        h.add(static_cast<std::int32_t>(e.joint.generation));
        h.add(static_cast<std::int32_t>(e.reason));
        h.add(e.separation);
        if (e.reaction != 0.0f) h.add(e.reaction);
    }
    h.add(static_cast<std::int32_t>(w.discarded.size()));
    for (BodyId b : w.discarded) {
        h.add(b.index);
        h.add(static_cast<std::int32_t>(b.generation));
    }
    h.add(static_cast<std::int32_t>(w.edgeEvents.size()));
    for (const WorldEdgeEvent& e : w.edgeEvents) {
        h.add(e.body.index);
        h.add(static_cast<std::int32_t>(e.body.generation));
        h.add(e.reached);
    }
    const StepStats& s = w.stats;
    for (int value :
         {s.islandCount, s.bodyCount, s.jointCount, s.translationClamps, s.rotationClamps,
          s.positionIterations, s.contactCount, s.touchingCount, s.sleepingBodyCount,
          s.letGoJointCount, s.discardedBodyCount, s.edgeBodyCount}) {
        h.add(static_cast<std::int32_t>(value));
    }
    return h.value();
}

}  // namespace pivot
