// pivot-fuzz: runs the random-operation driver (fuzz_driver.h) and prints what it did.
//   pivot-fuzz [--seed N] [--operations N] [--trace] [--keep-going] [--check-every-operation]
//              [--dump-before N] [--no-extremes] [--require-finite] [--journal PREFIX]
//              [--verify-islands] [--verify-census]
//   pivot-fuzz --replay FILE
// Exit status 0 when every check held, 1 on a failure, 2 on bad arguments. --replay replays a
// journal written with --journal and exits with 3 if a body or joint turns non-finite, 4 if a
// body's state goes beyond the input limits.
// --verify-islands searches every step's islands and fails if a step whose islands would have
// been kept from the step before (nothing counted in IslandRevision changed) found others.
// --verify-census checks the contact census (model/contact_census.h) against the contacts at
// every contact update: a stale entry fails the step that finds it.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include "fuzz_driver.h"
#include "journal.h"
#include "solver/stepper.h"
#include "world/contact_manager.h"

namespace {

bool parseNumber(const char* text, long long& out) {
    char* end = nullptr;
    out = std::strtoll(text, &end, 10);
    return end != text && *end == '\0' && out >= 0;
}

int replay(const char* path) {
    std::ifstream in(path);
    if (!in) {
        std::fprintf(stderr, "cannot read %s\n", path);
        return 2;
    }
    pivot::fuzz::ReplayResult r = pivot::fuzz::replay(in);
    if (!r.error.empty()) {
        std::fprintf(stderr, "%s\n", r.error.c_str());
        return 2;
    }
    std::printf("%d lines: %d calls returned, %d refused, %d skipped\n", r.lines, r.applied,
                r.refused, r.skipped);
    std::printf("let-go joints reported: %ld; discarded body states: %ld\n", r.letGoJoints,
                r.discardedBodies);
    if (r.nonFiniteLine > 0) {
        std::printf("non-finite after the step of line %d: %s\n", r.nonFiniteLine,
                    r.nonFinite.c_str());
        return 3;
    }
    if (r.beyondLimitsLine > 0) {
        std::printf("beyond the input limits after the step of line %d: %s\n", r.beyondLimitsLine,
                    r.beyondLimits.c_str());
        return 4;
    }
    std::printf("every body and joint finite, every body within the input limits\n");
    return 0;
}

int usage() {
    std::fprintf(stderr,
                 "usage: pivot-fuzz [--seed N] [--operations N] [--trace] [--keep-going]\n"
                 "                  [--check-every-operation] [--dump-before N]\n"
                 "                  [--no-extremes] [--require-finite] [--journal PREFIX]\n"
                 "                  [--verify-islands] [--verify-census]\n"
                 "       pivot-fuzz --replay FILE\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    pivot::fuzz::Options options;
    for (int i = 1; i < argc; ++i) {
        long long value = 0;
        if (std::strcmp(argv[i], "--seed") == 0 && i + 1 < argc &&
            parseNumber(argv[i + 1], value)) {
            options.seed = static_cast<std::uint64_t>(value);
            ++i;
        } else if (std::strcmp(argv[i], "--operations") == 0 && i + 1 < argc &&
                   parseNumber(argv[i + 1], value)) {
            options.operations = static_cast<long>(value);
            ++i;
        } else if (std::strcmp(argv[i], "--trace") == 0) {
            options.trace = true;
        } else if (std::strcmp(argv[i], "--dump-before") == 0 && i + 1 < argc &&
                   parseNumber(argv[i + 1], value)) {
            options.dumpBefore = static_cast<long>(value);
            ++i;
        } else if (std::strcmp(argv[i], "--journal") == 0 && i + 1 < argc) {
            options.journalPrefix = argv[++i];
        } else if (std::strcmp(argv[i], "--replay") == 0 && i + 1 < argc) {
            return replay(argv[i + 1]);
        } else if (std::strcmp(argv[i], "--no-extremes") == 0) {
            options.extremes = false;
        } else if (std::strcmp(argv[i], "--require-finite") == 0) {
            options.requireFinite = true;
        } else if (std::strcmp(argv[i], "--check-every-operation") == 0) {
            options.checkEveryOperation = true;
        } else if (std::strcmp(argv[i], "--keep-going") == 0) {
            options.stopAtFirstFailure = false;
        } else if (std::strcmp(argv[i], "--verify-islands") == 0) {
            pivot::Stepper::setIslandReuse(pivot::Stepper::IslandReuse::Verify);
        } else if (std::strcmp(argv[i], "--verify-census") == 0) {
            pivot::ContactManager::setCensusChecks(true);
        } else {
            return usage();
        }
    }

    auto start = std::chrono::steady_clock::now();
    pivot::fuzz::Report report = pivot::fuzz::run(options);
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    std::printf(
        "pivot-fuzz seed %llu: %ld operations in %.1f s: %ld accepted, %ld rejected "
        "(each checked to change nothing), %ld steps, %ld worlds, up to %ld bodies and "
        "%ld touching contacts\n",
        static_cast<unsigned long long>(options.seed), report.operations, seconds, report.accepted,
        report.rejected, report.steps, report.worlds, report.maxBodies, report.maxContacts);
    std::printf(
        "snapshots: %ld restored into a second world and compared; damaged ones: %ld refused, "
        "%ld (re-sealed) restored and stepped\n",
        report.snapshots, report.damagedSnapshotsRefused, report.damagedSnapshotsRestored);
    std::printf(
        "refused as they must be: %ld calls from task callbacks and other threads during a step, "
        "%ld structural calls from query callbacks; %ld foreign restores left the old ids stale; "
        "%ld pairs of worlds that hashed alike went on alike\n",
        report.refusedDuringSteps, report.refusedInQueries, report.staleIdsChecked,
        report.equalFuturesChecked);
    std::printf("worlds that came to report a non-finite number: %zu",
                report.nonFiniteWorlds.size());
    for (std::size_t i = 0; i < report.nonFiniteWorlds.size() && i < 10; ++i) {
        std::printf("%s%ld", i == 0 ? " (first seen at operations " : ", ",
                    report.nonFiniteWorlds[i]);
    }
    std::printf("%s\n", report.nonFiniteWorlds.empty() ? "" : ")");
    std::printf("contained: %ld let-go joints reported, %ld non-finite body states discarded\n",
                report.letGoJoints, report.discardedBodies);
    for (const auto& [name, count] : report.byOperation) {
        std::printf("  %-32s %9ld accepted %9ld rejected\n", name.c_str(), count.accepted,
                    count.rejected);
    }
    const std::uint64_t misKept = pivot::Stepper::islandsMisKept();
    std::printf("steps whose kept islands would have differed from the search's: %llu\n",
                static_cast<unsigned long long>(misKept));
    if (misKept > 0) report.failures.push_back("islands kept although the search found others");
    if (report.failures.empty()) {
        for (const std::string& j : report.journals)
            std::printf("journal written: %s\n", j.c_str());
        std::printf("no failures\n");
        return 0;
    }
    std::printf("%zu failure(s); rerun with --trace --operations N to see the calls:\n",
                report.failures.size());
    for (const std::string& f : report.failures) std::printf("  %s\n", f.c_str());
    for (const std::string& j : report.journals) std::printf("journal written: %s\n", j.c_str());
    return 1;
}
