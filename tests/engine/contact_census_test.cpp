// The contact census (model/contact_census.h): the summary of every contact slot that the
// passes over all contacts read instead of the contacts. A stale entry would drop a contact
// from the islands or from continuous collision without a sign, so the world below is put
// through everything that changes a contact's flags while the manager checks its census at
// every update.
#include <gtest/gtest.h>

#include <vector>

#include "model/contact_census.h"
#include "pivot/pivot.h"
#include "world/contact_manager.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;

struct CensusChecks {
    CensusChecks() { ContactManager::setCensusChecks(true); }
    ~CensusChecks() { ContactManager::setCensusChecks(false); }
};

Contact touchingContact(std::int32_t a, std::int32_t b, std::uint64_t serial) {
    Contact c;
    c.edges[0].body = a;
    c.edges[1].body = b;
    c.serial = serial;
    c.touching = true;
    return c;
}

}  // namespace

TEST(ContactCensus, SummarisesEachSlotAndNoticesAChangeNotRecorded) {
    SlotPool<Contact> contacts;
    ContactCensus census;
    const std::int32_t first = contacts.insert(touchingContact(3, 4, 7));
    const std::int32_t second = contacts.insert(touchingContact(5, 6, 8));
    census.grow(contacts.capacity());
    census.record(first, contacts[first]);
    census.record(second, contacts[second]);
    EXPECT_TRUE(census.matches(contacts));
    EXPECT_TRUE(census[first].solid());
    EXPECT_EQ(census[second].bodies[0], 5);
    EXPECT_EQ(census[second].serial, 8u);

    contacts[second].enabled = false;  // as a pre-solve answer would, not recorded
    EXPECT_FALSE(census.matches(contacts));
    census.record(second, contacts[second]);
    EXPECT_TRUE(census.matches(contacts));
    EXPECT_FALSE(census[second].solid());
    EXPECT_FALSE(census[second].blocking());

    contacts.erase(first);  // erased, not forgotten
    EXPECT_FALSE(census.matches(contacts));
    census.forget(first);
    EXPECT_TRUE(census.matches(contacts));
    EXPECT_FALSE(census[first].alive());

    ContactCensus rebuilt;
    rebuilt.rebuild(contacts);
    EXPECT_TRUE(rebuilt.matches(contacts));
}

TEST(ContactCensus, StaysTrueThroughEverythingThatChangesAContact) {
    const CensusChecks checks;
    World world{oneSubstepDef()};
    BodyDef groundDef;
    const BodyId ground = world.createBody(groundDef);
    world.createShape(ground, ShapeDef{}, Polygon::box(20.0f, 0.5f));
    // A thin wall and a bullet fired at it: continuous collision's impacts.
    BodyDef wallDef;
    wallDef.position = {12.0f, 3.0f};
    world.createShape(world.createBody(wallDef), ShapeDef{}, Polygon::box(0.05f, 2.0f));

    std::vector<BodyId> boxes;
    std::vector<ShapeId> shapes;
    for (int i = 0; i < 30; ++i) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {-6.0f + 0.9f * static_cast<float>(i % 10),
                        1.0f + static_cast<float>(i / 10)};
        const BodyId body = world.createBody(def);
        ShapeDef shape;
        shape.enablePreSolve = i % 3 == 0;
        shapes.push_back(world.createShape(body, shape, Polygon::box(0.4f, 0.4f)));
        boxes.push_back(body);
    }
    BodyDef bulletDef;
    bulletDef.type = BodyType::Dynamic;
    bulletDef.bullet = true;
    bulletDef.position = {0.0f, 3.0f};
    bulletDef.linearVelocity = {400.0f, 0.0f};
    const BodyId bullet = world.createBody(bulletDef);
    world.createShape(bullet, ShapeDef{}, Circle{{0.0f, 0.0f}, 0.1f});

    // The asked contacts are disabled on odd steps: the answers flip their enabled flag.
    int step = 0;
    world.setPreSolveCallback([&](const ContactData&) { return step % 2 == 0; });
    std::vector<std::uint8_t> saved;
    int impacts = 0;
    for (step = 0; step < 240; ++step) {
        ASSERT_NO_THROW(world.step(kDt)) << "step " << step;
        impacts += world.lastStepStats().impactCount;
        if (step == 20) {
            Filter apart;
            apart.groupIndex = -1;
            world.setShapeFilter(shapes[1], apart);
            world.setShapeFilter(shapes[2], apart);
        }
        if (step == 30) world.setShapeSensor(shapes[4], true);
        if (step == 40) world.setShapeSensor(shapes[4], false);
        if (step == 50)
            world.createJoint(RevoluteJointDef::atWorldAnchor(boxes[5], boxes[6], {-1.0f, 1.0f}));
        if (step == 60) world.setBodyType(boxes[7], BodyType::Static);
        if (step == 70) world.setBodyType(boxes[7], BodyType::Dynamic);
        if (step == 80) world.destroyShape(shapes[8]);
        if (step == 90) world.destroyBody(boxes[9]);
        if (step == 100) saved = world.snapshot();
        if (step == 150) world.restore(saved);
    }
    EXPECT_GT(impacts, 0);  // the bullet met the wall within a step
    EXPECT_GT(world.lastStepStats().touchingCount, 0);
}
