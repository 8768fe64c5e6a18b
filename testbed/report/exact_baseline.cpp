#include "report/exact_baseline.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "report/page_text.h"
#include "report/trials.h"
#include "scenes/scene.h"

namespace pivot::report {

namespace {

// The bodies and pins of a scene as the projection sees them: each dynamic body's centre, angle,
// mass and inertia (static bodies are fixed: index -1), each pin's bodies and local arms (from
// the centre of mass, in the body's frame).
struct Pin {
    int a = -1, b = -1;  // dynamic body indices, -1 for a fixed one
    double armA[2] = {0, 0}, armB[2] = {0, 0};
    double fixedA[3] = {0, 0, 0}, fixedB[3] = {0, 0, 0};  // x, y, angle of a fixed body
};
struct System {
    std::vector<BodyId> bodies;  // dynamic
    std::vector<double> mass, inertia;
    std::vector<Pin> pins;
};

struct Poses {
    std::vector<double> q;  // x, y, angle per dynamic body
};

System systemOf(const World& world, const std::vector<JointId>& joints) {
    System s;
    auto indexOf = [&](BodyId body) -> int {
        if (world.bodyType(body) != BodyType::Dynamic) return -1;
        for (std::size_t i = 0; i < s.bodies.size(); ++i) {
            if (s.bodies[i] == body) return static_cast<int>(i);
        }
        s.bodies.push_back(body);
        s.mass.push_back(world.bodyMass(body));
        // About the centre of mass.
        const Vec2 lc = world.bodyLocalCenter(body);
        s.inertia.push_back(world.bodyRotationalInertia(body) -
                            world.bodyMass(body) * double(lc.x * lc.x + lc.y * lc.y));
        return static_cast<int>(s.bodies.size()) - 1;
    };
    for (JointId j : joints) {
        if (world.jointType(j) != JointType::Revolute || world.jointLimit(j).enabled) {
            throw std::logic_error("exact baseline: a joint that is not a free revolute pin");
        }
        Pin pin;
        const BodyId bodyA = world.jointBodyA(j), bodyB = world.jointBodyB(j);
        pin.a = indexOf(bodyA);
        pin.b = indexOf(bodyB);
        const Vec2 la = world.jointLocalAnchorA(j) - world.bodyLocalCenter(bodyA);
        const Vec2 lb = world.jointLocalAnchorB(j) - world.bodyLocalCenter(bodyB);
        pin.armA[0] = la.x;
        pin.armA[1] = la.y;
        pin.armB[0] = lb.x;
        pin.armB[1] = lb.y;
        const Vec2 ca = world.bodyWorldCenter(bodyA), cb = world.bodyWorldCenter(bodyB);
        pin.fixedA[0] = ca.x;
        pin.fixedA[1] = ca.y;
        pin.fixedA[2] = world.bodyAngle(bodyA);
        pin.fixedB[0] = cb.x;
        pin.fixedB[1] = cb.y;
        pin.fixedB[2] = world.bodyAngle(bodyB);
        s.pins.push_back(pin);
    }
    return s;
}

Poses posesOf(const World& world, const System& s) {
    Poses p;
    for (BodyId body : s.bodies) {
        const Vec2 c = world.bodyWorldCenter(body);
        p.q.push_back(c.x);
        p.q.push_back(c.y);
        p.q.push_back(world.bodyAngle(body));
    }
    return p;
}

// A pin's anchor on one side: its world point and d(point)/d(angle).
void anchor(const double* pose, const double* arm, double point[2], double dAngle[2]) {
    const double c = std::cos(pose[2]), s = std::sin(pose[2]);
    const double rx = c * arm[0] - s * arm[1], ry = s * arm[0] + c * arm[1];
    point[0] = pose[0] + rx;
    point[1] = pose[1] + ry;
    dAngle[0] = -ry;
    dAngle[1] = rx;
}

// Solves A x = b in place (A n x n, row-major) by Gaussian elimination with partial pivoting;
// false if A is singular to working precision.
bool solveDense(std::vector<double>& A, std::vector<double>& b, int n) {
    for (int k = 0; k < n; ++k) {
        int pivot = k;
        for (int i = k + 1; i < n; ++i) {
            if (std::fabs(A[i * n + k]) > std::fabs(A[pivot * n + k])) pivot = i;
        }
        if (std::fabs(A[pivot * n + k]) < 1e-300) return false;
        if (pivot != k) {
            for (int j = 0; j < n; ++j) std::swap(A[k * n + j], A[pivot * n + j]);
            std::swap(b[k], b[pivot]);
        }
        for (int i = k + 1; i < n; ++i) {
            const double f = A[i * n + k] / A[k * n + k];
            if (f == 0.0) continue;
            for (int j = k; j < n; ++j) A[i * n + j] -= f * A[k * n + j];
            b[i] -= f * b[k];
        }
    }
    for (int k = n - 1; k >= 0; --k) {
        double sum = b[k];
        for (int j = k + 1; j < n; ++j) sum -= A[k * n + j] * b[j];
        b[k] = sum / A[k * n + k];
    }
    return true;
}

constexpr double kClosed = 1e-9;  // m: every pin this close counts as converged
constexpr int kMostNewtonSteps = 50;

// One row of the pin system: its value and its Jacobian on at most two bodies (x, y, angle each).
struct Row {
    int body[2] = {-1, -1};
    double j[2][3] = {{0, 0, 0}, {0, 0, 0}};
};

// The mass-weighted closest poses to `p` with every pin closed (Newton's method, each step the
// minimum-norm correction in the mass metric); nothing if it does not converge (a torn chain's
// poses can be too far from any closed ones).
std::optional<Poses> project(const System& s, Poses p) {
    const int rows = 2 * static_cast<int>(s.pins.size());
    const int bodies = static_cast<int>(s.bodies.size());
    std::vector<Row> J(static_cast<std::size_t>(rows));
    std::vector<double> C(static_cast<std::size_t>(rows)), A, lambda;
    std::vector<std::vector<int>> rowsOf(static_cast<std::size_t>(bodies));
    for (int step = 0; step <= kMostNewtonSteps; ++step) {
        for (auto& list : rowsOf) list.clear();
        double worst = 0.0;
        for (std::size_t k = 0; k < s.pins.size(); ++k) {
            const Pin& pin = s.pins[k];
            const double* poseA = pin.a >= 0 ? &p.q[3 * pin.a] : pin.fixedA;
            const double* poseB = pin.b >= 0 ? &p.q[3 * pin.b] : pin.fixedB;
            double pa[2], da[2], pb[2], db[2];
            anchor(poseA, pin.armA, pa, da);
            anchor(poseB, pin.armB, pb, db);
            for (int r = 0; r < 2; ++r) {
                const int row = static_cast<int>(2 * k) + r;
                C[row] = pb[r] - pa[r];
                worst = std::max(worst, std::fabs(C[row]));
                Row& out = J[row];
                out = Row{};
                out.body[0] = pin.a;
                out.body[1] = pin.b;
                out.j[0][r] = -1.0;
                out.j[0][2] = -da[r];
                out.j[1][r] = 1.0;
                out.j[1][2] = db[r];
                if (pin.a >= 0) rowsOf[pin.a].push_back(row);
                if (pin.b >= 0) rowsOf[pin.b].push_back(row);
            }
        }
        if (worst <= kClosed) return p;
        if (step == kMostNewtonSteps) break;
        // (J M^-1 J^T) lambda = C, then x -= M^-1 J^T lambda; each body adds the products of
        // the rows that touch it.
        A.assign(static_cast<std::size_t>(rows) * rows, 0.0);
        auto side = [&](const Row& row, int body) { return row.body[0] == body ? 0 : 1; };
        for (int b = 0; b < bodies; ++b) {
            const double inv[3] = {1.0 / s.mass[b], 1.0 / s.mass[b], 1.0 / s.inertia[b]};
            for (int i : rowsOf[b]) {
                const double* ji = J[i].j[side(J[i], b)];
                for (int k : rowsOf[b]) {
                    const double* jk = J[k].j[side(J[k], b)];
                    A[static_cast<std::size_t>(i) * rows + k] +=
                        ji[0] * inv[0] * jk[0] + ji[1] * inv[1] * jk[1] + ji[2] * inv[2] * jk[2];
                }
            }
        }
        lambda = C;
        if (!solveDense(A, lambda, rows)) return std::nullopt;
        for (int i = 0; i < rows; ++i) {
            for (int side = 0; side < 2; ++side) {
                const int b = J[i].body[side];
                if (b < 0) continue;
                p.q[3 * b] -= J[i].j[side][0] * lambda[i] / s.mass[b];
                p.q[3 * b + 1] -= J[i].j[side][1] * lambda[i] / s.mass[b];
                p.q[3 * b + 2] -= J[i].j[side][2] * lambda[i] / s.inertia[b];
            }
        }
    }
    return std::nullopt;
}

// m: how far the strategy's poses are from the exact ones, the largest over bodies of the
// centre's distance plus the angle's difference times the radius of gyration.
double distance(const System& s, const Poses& a, const Poses& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
        const double dx = a.q[3 * i] - b.q[3 * i], dy = a.q[3 * i + 1] - b.q[3 * i + 1];
        const double gyration = std::sqrt(s.inertia[i] / s.mass[i]);
        const double dAngle = std::fabs(a.q[3 * i + 2] - b.q[3 * i + 2]) * gyration;
        worst = std::max(worst, std::sqrt(dx * dx + dy * dy) + dAngle);
    }
    return worst;
}

struct Trial {
    double worst = 0.0;          // m, the largest distance from the exact poses
    double worstSeparation = 0;  // m, the largest pin separation of the strategy's own steps
    bool blewUp = false;
    int unsolved = 0;  // steps whose poses Newton could not close
};

Trial runTrial(const scenes::SceneInfo& info, PositionSolver solver, std::uint32_t seed,
               int steps) {
    scenes::SceneOptions options;
    options.solver = solver;
    options.perturbation = seed;
    scenes::Scene scene = scenes::buildScene(info, options);
    World& world = *scene.world;
    const System system = systemOf(world, scene.joints);
    Trial t;
    const float dt = 1.0f / options.hz;
    for (int i = 0; i < steps; ++i) {
        if (scene.beforeStep) scene.beforeStep(scene, i);
        const std::vector<std::uint8_t> before = world.snapshot();
        world.step(dt, kBox2D241VelocityIterations, 0);
        const std::optional<Poses> exact = project(system, posesOf(world, system));
        world.restore(before);
        world.step(dt, kBox2D241VelocityIterations, kBox2D241PositionIterations);
        if (scenes::isBlownUp(scene)) {
            t.blewUp = true;
            break;
        }
        if (exact) {
            t.worst = std::max(t.worst, distance(system, posesOf(world, system), *exact));
        } else {
            ++t.unsolved;
        }
        for (JointId j : scene.joints) {
            t.worstSeparation = std::max(t.worstSeparation, double(world.jointSeparation(j)));
        }
    }
    return t;
}

}  // namespace

const std::vector<std::string>& exactBaselineScenes() {
    static const std::vector<std::string> names = {"pendulum_20", "double_pendulum", "chain"};
    return names;
}

ExactBaseline runExactBaseline(int steps, int threads,
                               const std::function<void(const std::string&)>& progress) {
    ExactBaseline out;
    std::ostringstream md;
    md << "## Against the exact projection\n\n"
       << "Each strategy's position correction measured against the converged answer: at every "
          "step the same state is also stepped without its position phase (a snapshot "
          "restored, 0 position iterations) and those poses are projected onto the pins "
          "exactly, by Newton steps with a dense factorisation of the whole joint system in "
          "double precision, to "
       << num("%g", kClosed)
       << " m (the mass-weighted closest poses: where unlimited exact position iterations go). "
          "*from exact* is how far the strategy's own step left the bodies from those poses, the "
          "largest over bodies (centre distance plus angle times radius of gyration) and steps; "
          "*max sep* is the strategy's own largest pin separation. One substep of 8 velocity "
          "and 3 position iterations; medians over "
       << kTrials
       << " perturbed runs [range]. Baumgarte, soft step and XPBD correct inside or "
          "beside the velocity phase, so their distance also holds what their velocity phase "
          "did differently; for the NGS strategies and pseudo velocities it is the position "
          "phase alone.\n\n"
       << "| scene | strategy | from exact (m) | max sep (m) | blew up | steps without an exact "
          "answer |\n"
       << "| --- | --- | --- | --- | ---: | ---: |\n";
    out.csv = "scene,solver,seed,from_exact_m,max_separation_m,blew_up,steps_without_exact\n";
    for (const std::string& name : exactBaselineScenes()) {
        if (progress) progress("exact baseline: " + name);
        const scenes::SceneInfo* info = scenes::findScene(name);
        if (!info) throw std::logic_error("exact baseline: no scene " + name);
        for (int s = 0; s < kPositionSolverCount; ++s) {
            const PositionSolver solver = static_cast<PositionSolver>(s);
            std::vector<Trial> trials(kTrials);
            runJobs(trials.size(), threads, [&](std::size_t t) {
                trials[t] = runTrial(*info, solver, trialSeed(static_cast<int>(t)), steps);
            });
            out.runs += kTrials;
            std::vector<double> worst, separation;
            int blewUp = 0;
            long unsolved = 0;
            for (std::size_t t = 0; t < trials.size(); ++t) {
                out.csv += name + ',' + positionSolverName(solver) + ',' +
                           std::to_string(trialSeed(static_cast<int>(t))) + ',' +
                           num("%.6g", trials[t].worst) + ',' +
                           num("%.6g", trials[t].worstSeparation) + ',' +
                           (trials[t].blewUp ? "1" : "0") + ',' +
                           std::to_string(trials[t].unsolved) + '\n';
            }
            for (const Trial& t : trials) {
                worst.push_back(t.worst);
                separation.push_back(t.worstSeparation);
                blewUp += t.blewUp ? 1 : 0;
                unsolved += t.unsolved;
            }
            md << "| " << name << " | " << positionSolverName(solver) << " | "
               << spreadOf(worst).text() << " | " << spreadOf(separation).text() << " | " << blewUp
               << "/" << kTrials << " | " << unsolved << " |\n";
        }
    }
    md << "\n";
    out.markdown = md.str();
    return out;
}

}  // namespace pivot::report
