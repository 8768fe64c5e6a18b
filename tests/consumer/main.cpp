// The README example, built against the installed package: a ball on a FullNGS pin.
#include <pivot/pivot.h>

#include <cstdio>

int main() {
    pivot::World world;  // gravity (0, -10); 8 substeps of 2/1 iterations; FullNGS joints

    pivot::BodyId ground = world.createBody(pivot::BodyDef{});

    pivot::BodyDef ballDef;
    ballDef.type = pivot::BodyType::Dynamic;
    ballDef.position = {5.0f, 10.0f};
    pivot::BodyId ball = world.createBody(ballDef);
    world.createShape(ball, pivot::ShapeDef{}, pivot::Circle{{0.0f, 0.0f}, 0.5f});

    pivot::RevoluteJointDef jd =
        pivot::RevoluteJointDef::atWorldAnchor(ground, ball, {0.0f, 10.0f});
    jd.positionSolver = pivot::PositionSolver::FullNGS;
    pivot::JointId pin = world.createJoint(jd);

    for (int i = 0; i < 600; ++i) world.step(1.0f / 60.0f);

    float separation = world.jointSeparation(pin);
    std::printf("consumer: separation after 10 s = %g m\n", separation);
    return separation < pivot::kLinearSlop ? 0 : 1;
}
