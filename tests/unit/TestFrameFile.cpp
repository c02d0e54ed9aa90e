// One frame file: exact round trip, and every kind of damage detected with a clear message.
#include "cache/FrameFile.h"
#include "support/TestMain.h"
#include "unit/CacheTestData.h"

#include <QtTest/QtTest>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

using namespace airtrap;
using namespace airtrap::testing;

namespace {

const std::string kPath = "/cache/frame_0007.atf";

template <typename T>
void put(std::vector<std::uint8_t>& bytes, std::size_t offset, T value) {
    std::memcpy(bytes.data() + offset, &value, sizeof value);
}

//! Recomputes payload size and both checksums after a test edits the bytes on purpose, so that
//! the check under test is the only one that can fail (offsets from docs/CACHE_FORMAT.md).
void resealFrame(std::vector<std::uint8_t>& bytes) {
    const std::uint64_t payload = bytes.size() - kFrameHeaderSize;
    put<std::uint64_t>(bytes, 16, payload);
    put<std::uint32_t>(bytes, 24, computeCrc32(bytes.data() + kFrameHeaderSize, payload));
    put<std::uint32_t>(bytes, 28, computeCrc32(bytes.data(), 28));
}

//! Three bodies whose values exercise every bit pattern the BODY chunk must keep.
std::vector<RigidBodyState> threeBodies() {
    std::vector<RigidBodyState> bodies(3);
    bodies[0].position = Vec3d(1.5, -0.0, 2.25);
    bodies[1].position = Vec3d(0.1, 0.2, 0.3);
    bodies[1].orientation = Quatd(Eigen::AngleAxisd(0.7, Vec3d(1, 2, 3).normalized()));
    bodies[1].linearVelocity = Vec3d(-1e-300, std::numeric_limits<double>::denorm_min(), 3.0);
    bodies[1].angularVelocity = Vec3d(0.0, 12.5, -7.0 / 3.0);
    bodies[2].orientation = Quatd(-0.5, 0.5, -0.5, 0.5);
    bodies[2].angularVelocity = Vec3d(std::numeric_limits<double>::max(), 1.0 / 3.0, -0.0);
    return bodies;
}

//! Two bubbles, one with a negative zero and a denormal the BUBL chunk must keep.
std::vector<BubbleState> twoBubbles() {
    std::vector<BubbleState> bubbles(2);
    bubbles[0].id = 3;
    bubbles[0].birthFrame = 7;
    bubbles[0].radius = 0.015;
    bubbles[0].body.position = Vec3d(0.2, 0.1, 0.3);
    bubbles[0].age = 0.25;
    bubbles[0].areaFractionInWater = 0.8;
    bubbles[0].pocketVolume = 2.5e-5;
    bubbles[1].id = 16;
    bubbles[1].birthFrame = 9;
    bubbles[1].radius = 0.03;
    bubbles[1].body.linearVelocity = Vec3d(-0.0, std::numeric_limits<double>::denorm_min(), 0.2);
    bubbles[1].floatingTime = 1.0 / 3.0;
    bubbles[1].surroundings.waterVelocity = Vec3d(0.1, -0.0, 1.0 / 7.0);
    bubbles[1].surroundings.impactSpeed = 0.75;
    bubbles[1].surroundings.wettedShare = 5.0 / 14.0;
    bubbles[1].surroundings.floating = true;
    bubbles[1].surroundings.measured = true;
    return bubbles;
}

//! A hand-written state and stats (no random distributions, whose output differs between
//! standard libraries) for the golden-bytes test.
SimulationState fixedState() {
    SimulationState state;
    state.frame = 3;
    state.time = 0.125;
    state.steps = 77;
    state.lastTimeStep = 1e-4;
    state.lastMaxAcceleration = 9.81;
    state.nextParticleId = 3;
    for (int i = 0; i < 3; ++i)
        state.fluid.push(Vec3f(0.1f * i, 0.2f, -0.3f * i), Vec3f(1.0f, -float(i), 0.5f),
                         1000.0f + i, std::uint32_t(i));
    return state;
}

FrameStats fixedStats() {
    FrameStats stats;
    stats.wallSeconds = 0.5;
    stats.stepsInFrame = 12;
    stats.maxSpeed = 2.5;
    stats.meanDensity = 1001.0;
    stats.phaseSeconds = {{"forces", 0.25}, {"neighbours", 0.125}};
    return stats;
}

//! Offset of the last chunk's header, walking the chunk list from the payload start.
std::size_t lastChunkOffset(const std::vector<std::uint8_t>& bytes) {
    std::size_t at = kFrameHeaderSize;
    std::size_t last = at;
    while (at < bytes.size()) {
        last = at;
        std::uint64_t length = 0;
        std::memcpy(&length, bytes.data() + at + 4, 8);
        at += 12 + length;
    }
    return last;
}

//! Offset of the first chunk tagged `tag`.
std::size_t chunkOffset(const std::vector<std::uint8_t>& bytes, const char* tag) {
    std::size_t at = kFrameHeaderSize;
    while (at < bytes.size() && std::memcmp(bytes.data() + at, tag, 4) != 0) {
        std::uint64_t length = 0;
        std::memcpy(&length, bytes.data() + at + 4, 8);
        at += 12 + length;
    }
    return at;
}

//! `bytes` without the chunk at `at`, as a frame written before that chunk existed.
std::vector<std::uint8_t> withoutChunk(std::vector<std::uint8_t> bytes, std::size_t at) {
    std::uint64_t length = 0;
    std::memcpy(&length, bytes.data() + at + 4, 8);
    bytes.erase(bytes.begin() + std::ptrdiff_t(at),
                bytes.begin() + std::ptrdiff_t(at + 12 + length));
    resealFrame(bytes);
    return bytes;
}

QString corruptMessage(const std::vector<std::uint8_t>& bytes) {
    const auto error = errorOf([&] { decodeFrame(bytes, kPath); });
    if (!error)
        return "decoded without error";
    if (error->kind() != ErrorKind::CacheCorrupt)
        return "wrong error kind: " + QString::fromStdString(error->what());
    return QString::fromStdString(error->what());
}

} // namespace

class TestFrameFile : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void roundTripIsExact() {
        const SimulationState state = randomState(7, 500, 1);
        const FrameStats stats = randomStats(2);
        const std::vector<std::uint8_t> bytes = encodeFrame(state, stats);
        const FrameData decoded = decodeFrame(bytes, kPath);
        QVERIFY(decoded.state == state);
        QVERIFY(decoded.stats == stats);
        QCOMPARE(decoded.stats.phaseSeconds.size(), std::size_t(4));
        // Re-encoding gives the same bytes: bit patterns survive, not just values.
        QVERIFY(encodeFrame(decoded.state, decoded.stats) == bytes);
    }

    void specialValuesKeepTheirBits() {
        SimulationState state = randomState(3, 3, 5);
        state.time = -0.0;
        state.lastTimeStep = std::numeric_limits<double>::denorm_min();
        state.lastMaxAcceleration = std::numeric_limits<double>::infinity();
        state.fluid.densities[0] = -0.0f;
        state.fluid.densities[1] = std::numeric_limits<float>::denorm_min();
        const std::vector<std::uint8_t> bytes = encodeFrame(state, FrameStats{});
        const FrameData decoded = decodeFrame(bytes, kPath);
        QVERIFY(std::signbit(decoded.state.time));
        QVERIFY(std::signbit(decoded.state.fluid.densities[0]));
        QVERIFY(encodeFrame(decoded.state, decoded.stats) == bytes);
    }

    void emptyParticleSet() {
        const SimulationState state = randomState(1, 0, 9);
        const FrameData decoded = decodeFrame(encodeFrame(state, FrameStats{}), kPath);
        QVERIFY(decoded.state == state);
        QVERIFY(decoded.state.fluid.empty());
    }

    void truncatedFileDetected() {
        const std::vector<std::uint8_t> bytes = encodeFrame(randomState(7, 20, 3), randomStats(3));
        std::vector<std::uint8_t> cut(bytes.begin(), bytes.end() - 1);
        const QString message = corruptMessage(cut);
        QVERIFY2(message.contains(QString::fromStdString(kPath)), qPrintable(message));
        QVERIFY2(message.contains(QString("truncated: expected %1 bytes, found %2")
                                      .arg(bytes.size())
                                      .arg(cut.size())),
                 qPrintable(message));
        for (std::size_t size : {std::size_t(0), std::size_t(10), std::size_t(40)}) {
            cut.assign(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(size));
            QVERIFY2(corruptMessage(cut).contains("truncated"), qPrintable(corruptMessage(cut)));
        }
    }

    void everyFlippedByteDetected() {
        const std::vector<std::uint8_t> bytes = encodeFrame(randomState(7, 4, 4), randomStats(4));
        for (std::size_t i = 0; i < bytes.size(); ++i) {
            std::vector<std::uint8_t> damaged = bytes;
            damaged[i] ^= 0x10;
            const QString message = corruptMessage(damaged);
            QVERIFY2(message.startsWith(QString::fromStdString(kPath)),
                     qPrintable(QString("byte %1: %2").arg(i).arg(message)));
        }
        std::vector<std::uint8_t> damaged = bytes;
        damaged[bytes.size() / 2] ^= 0x01;
        QVERIFY(corruptMessage(damaged).contains("checksum mismatch"));
    }

    void trailingBytesDetected() {
        std::vector<std::uint8_t> bytes = encodeFrame(randomState(7, 4, 4), randomStats(4));
        bytes.push_back(0);
        QVERIFY(corruptMessage(bytes).contains("trailing"));
    }

    void wrongMagicDetected() {
        std::vector<std::uint8_t> bytes = encodeFrame(randomState(7, 4, 4), randomStats(4));
        bytes[0] = 'X';
        QVERIFY(corruptMessage(bytes).contains("wrong magic"));
    }

    void newerVersionNamed() {
        std::vector<std::uint8_t> bytes = encodeFrame(randomState(7, 4, 4), randomStats(4));
        put<std::uint32_t>(bytes, 4, kFrameFormatVersion + 1);
        resealFrame(bytes);
        const QString message = corruptMessage(bytes);
        QVERIFY2(message.contains("newer Airtrap"), qPrintable(message));
        QVERIFY2(message.contains(QString("version %1").arg(kFrameFormatVersion + 1)),
                 qPrintable(message));
    }

    void attributeCountMismatchDetected() {
        std::vector<std::uint8_t> bytes = encodeFrame(randomState(7, 4, 4), randomStats(4));
        // STAT is the first chunk: body at 32 + 12; particle count after i32+5×8+u32 = 40 bytes.
        QCOMPARE(std::memcmp(bytes.data() + 32, "STAT", 4), 0);
        put<std::uint64_t>(bytes, 32 + 12 + 40, 5);
        resealFrame(bytes);
        const QString message = corruptMessage(bytes);
        QVERIFY2(message.contains("has 4 elements, the frame has 5 particles"),
                 qPrintable(message));
    }

    void unknownChunkSkipped() {
        const SimulationState state = randomState(7, 10, 6);
        std::vector<std::uint8_t> bytes = encodeFrame(state, FrameStats{});
        const char tag[4] = {'X', 'T', 'R', 'A'};
        const std::uint64_t length = 3;
        bytes.insert(bytes.end(), tag, tag + 4);
        bytes.resize(bytes.size() + 8 + length, 0xab);
        put<std::uint64_t>(bytes, bytes.size() - 8 - length, length);
        resealFrame(bytes);
        QVERIFY(decodeFrame(bytes, kPath).state == state);
    }

    void bodiesRoundTripIsExact() {
        SimulationState state = randomState(5, 30, 8);
        state.bodies = threeBodies();
        const FrameStats stats = randomStats(5);
        const std::vector<std::uint8_t> bytes = encodeFrame(state, stats);
        const FrameData decoded = decodeFrame(bytes, kPath);
        QVERIFY(decoded.state == state);
        QCOMPARE(decoded.state.bodies.size(), std::size_t(3));
        QVERIFY(std::signbit(decoded.state.bodies[0].position.y()));
        QVERIFY(std::signbit(decoded.state.bodies[2].angularVelocity.z()));
        QCOMPARE(decoded.state.bodies[2].orientation.w(), -0.5); // stored w first, not negated
        QVERIFY(encodeFrame(decoded.state, decoded.stats) == bytes);
    }

    void bodyChunkLayoutIsDocumented() {
        SimulationState state = randomState(5, 2, 8);
        state.bodies = threeBodies();
        const std::vector<std::uint8_t> bytes = encodeFrame(state, FrameStats{});
        const std::size_t at = lastChunkOffset(bytes);
        QCOMPARE(std::memcmp(bytes.data() + at, "BODY", 4), 0);
        std::uint64_t length = 0;
        std::uint32_t count = 0;
        std::memcpy(&length, bytes.data() + at + 4, 8);
        std::memcpy(&count, bytes.data() + at + 12, 4);
        QCOMPARE(count, 3u);
        QCOMPARE(length, std::uint64_t(4 + 3 * 13 * 8));
        // Body 1: X (3 f64), then q as w, x, y, z, then V, then ω.
        double record[13];
        std::memcpy(record, bytes.data() + at + 16 + 13 * 8, sizeof record);
        const RigidBodyState& body = state.bodies[1];
        QCOMPARE(record[2], body.position.z());
        QCOMPARE(record[3], body.orientation.w());
        QCOMPARE(record[6], body.orientation.z());
        QCOMPARE(record[7], body.linearVelocity.x());
        QCOMPARE(record[12], body.angularVelocity.z());
    }

    void corruptBodyChunkDetected() {
        SimulationState state = randomState(7, 4, 4);
        state.bodies = threeBodies();
        const std::vector<std::uint8_t> good = encodeFrame(state, randomStats(4));
        const std::size_t at = lastChunkOffset(good);
        // One double short: the count says 3 bodies, the body holds 2 and a bit.
        std::vector<std::uint8_t> bytes(good.begin(), good.end() - 8);
        put<std::uint64_t>(bytes, at + 4, 4 + 3 * 13 * 8 - 8);
        resealFrame(bytes);
        QString message = corruptMessage(bytes);
        QVERIFY2(message.startsWith(QString::fromStdString(kPath)), qPrintable(message));
        QVERIFY2(message.contains("chunk BODY is 308 bytes, expected 316 for 3 bodies"),
                 qPrintable(message));
        // A count that does not match the records.
        bytes = good;
        put<std::uint32_t>(bytes, at + 12, 4);
        resealFrame(bytes);
        message = corruptMessage(bytes);
        QVERIFY2(message.contains("expected 420 for 4 bodies"), qPrintable(message));
        // Too short to hold even the count.
        bytes.assign(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(at + 12 + 2));
        put<std::uint64_t>(bytes, at + 4, 2);
        resealFrame(bytes);
        message = corruptMessage(bytes);
        QVERIFY2(message.startsWith(QString::fromStdString(kPath) + ": chunk BODY"),
                 qPrintable(message));
    }

    void duplicateBodyChunkDetected() {
        SimulationState state = randomState(7, 4, 4);
        state.bodies = threeBodies();
        std::vector<std::uint8_t> bytes = encodeFrame(state, FrameStats{});
        const std::vector<std::uint8_t> chunk(
            bytes.begin() + static_cast<std::ptrdiff_t>(lastChunkOffset(bytes)), bytes.end());
        bytes.insert(bytes.end(), chunk.begin(), chunk.end());
        resealFrame(bytes);
        QVERIFY2(corruptMessage(bytes).contains("more than one BODY chunk"),
                 qPrintable(corruptMessage(bytes)));
    }

    void frameWithoutBodiesIsUnchanged() {
        // Size and CRC-32 of this frame as encoded before the BODY chunk existed: frames of scenes
        // without bodies, and caches written by older builds, stay byte-identical.
        const std::vector<std::uint8_t> bytes = encodeFrame(fixedState(), fixedStats());
        QCOMPARE(bytes.size(), std::size_t(401));
        QCOMPARE(computeCrc32(bytes.data(), bytes.size()), 0xC4EC37B4u);
        QVERIFY(decodeFrame(bytes, kPath).state.bodies.empty());
        // With bodies, the same chunks come first and BODY is appended after them.
        SimulationState withBodies = fixedState();
        withBodies.bodies = threeBodies();
        const std::vector<std::uint8_t> longer = encodeFrame(withBodies, fixedStats());
        QCOMPARE(longer.size(), bytes.size() + 12 + 4 + 3 * 13 * 8);
        QVERIFY(std::equal(bytes.begin() + kFrameHeaderSize, bytes.end(),
                           longer.begin() + kFrameHeaderSize));
    }

    void bubblesRoundTripIsExact() {
        SimulationState state = randomState(9, 20, 3);
        state.bodies = threeBodies();
        state.bubbles = twoBubbles();
        state.nextBubbleId = 17;
        state.bubblesDeleted.deleted = {4, 5, 2, 4, 7};
        state.bubblesDeleted.surfacedYoung = 3;
        FrameStats stats = randomStats(9);
        stats.bubbles.created = 3;
        stats.bubbles.deleted = {1, 0, 2, 0, 2};
        stats.bubbles.surfacedYoung = 1;
        const std::vector<std::uint8_t> bytes = encodeFrame(state, stats);
        const FrameData decoded = decodeFrame(bytes, kPath);
        QVERIFY(decoded.state == state);
        QVERIFY(decoded.stats == stats);
        QCOMPARE(decoded.state.nextBubbleId, 17u);
        QVERIFY(std::signbit(decoded.state.bubbles[1].body.linearVelocity.x()));
        QVERIFY(encodeFrame(decoded.state, decoded.stats) == bytes);
        // BUBL follows BODY: 80 bytes of count, next id and tallies, then 152 per bubble; BSUR
        // comes last: a count, then 42 bytes per bubble.
        const std::size_t at = chunkOffset(bytes, "BUBL");
        QVERIFY(at < bytes.size());
        std::uint64_t length = 0;
        std::memcpy(&length, bytes.data() + at + 4, 8);
        QCOMPARE(length, std::uint64_t(80 + 2 * 152));
        const std::size_t surroundingsAt = lastChunkOffset(bytes);
        QCOMPARE(std::memcmp(bytes.data() + surroundingsAt, "BSUR", 4), 0);
        std::memcpy(&length, bytes.data() + surroundingsAt + 4, 8);
        QCOMPARE(length, std::uint64_t(4 + 2 * 42));
        QVERIFY(std::signbit(decoded.state.bubbles[1].surroundings.waterVelocity.y()));
        // BSFD beside BUBL: the surfaced counts so far and in the frame, 32 bytes.
        const std::size_t surfacedAt = chunkOffset(bytes, "BSFD");
        QVERIFY(surfacedAt < bytes.size());
        std::memcpy(&length, bytes.data() + surfacedAt + 4, 8);
        QCOMPARE(length, std::uint64_t(32));
        QCOMPARE(decoded.state.bubblesDeleted.deleted[BubbleTally::Surfaced], std::uint64_t(7));
        QCOMPARE(decoded.stats.bubbles.surfacedYoung, std::uint64_t(1));
    }

    void framesWithoutSurfacedCountsReadAsNone() {
        SimulationState state = randomState(9, 4, 3);
        state.bubbles = twoBubbles();
        state.nextBubbleId = 9;
        state.bubblesDeleted.deleted = {1, 2, 0, 1, 5};
        const std::vector<std::uint8_t> bytes = encodeFrame(state, FrameStats{});
        const FrameData older = decodeFrame(withoutChunk(bytes, chunkOffset(bytes, "BSFD")), kPath);
        QCOMPARE(older.state.bubblesDeleted.deleted[BubbleTally::Surfaced], std::uint64_t(0));
        QCOMPARE(older.state.bubblesDeleted.deleted[BubbleTally::Floating], std::uint64_t(2));
        // A chunk of 24 bytes, one count short.
        std::vector<std::uint8_t> damaged = bytes;
        const std::size_t at = chunkOffset(damaged, "BSFD");
        put<std::uint64_t>(damaged, at + 4, 24);
        damaged.erase(damaged.begin() + std::ptrdiff_t(at + 12 + 24),
                      damaged.begin() + std::ptrdiff_t(at + 12 + 32));
        resealFrame(damaged);
        const QString message = corruptMessage(damaged);
        QVERIFY2(message.contains("chunk BSFD is 24 bytes, expected 32"), qPrintable(message));
    }

    void pressureSolveRoundTripIsExact() {
        SimulationState state = randomState(9, 6, 3);
        // A divergence-free bake's warm start: one value per particle that the last step moved
        // (the inflow after it may have added more, which start from zero).
        state.warmStart.divergence = {0.5f, -0.0f, 1e-30f, 3.0f, 0.25f};
        state.warmStart.density = {2.0f, 0.0f, std::numeric_limits<float>::denorm_min(), 7.5f,
                                   1.0f / 3.0f};
        FrameStats stats;
        stats.pressureSolve = {.steps = 17,
                               .divergenceIterations = 40,
                               .densityIterations = 95,
                               .meanDensityError = 8.5e-5,
                               .maxDensityError = 1.25e-4,
                               .unconvergedSteps = 1};
        const std::vector<std::uint8_t> bytes = encodeFrame(state, stats);
        const FrameData decoded = decodeFrame(bytes, kPath);
        QVERIFY(decoded.state == state);
        QVERIFY(decoded.stats.pressureSolve == stats.pressureSolve);
        QVERIFY(encodeFrame(decoded.state, decoded.stats) == bytes);
    }

    void framesWithoutPressureSolveReadAsWcsph() {
        SimulationState state = randomState(9, 6, 3);
        state.warmStart.divergence.assign(6, 1.0f);
        state.warmStart.density.assign(6, 2.0f);
        FrameStats stats;
        stats.pressureSolve.steps = 3;
        const std::vector<std::uint8_t> bytes = encodeFrame(state, stats);
        const FrameData older = decodeFrame(withoutChunk(bytes, chunkOffset(bytes, "PSOL")), kPath);
        QVERIFY(older.state.warmStart.empty());
        QCOMPARE(older.stats.pressureSolve.steps, std::uint64_t(0));
        QCOMPARE(older.state.fluid.size(), std::size_t(6));
        // A WCSPH frame has no PSOL chunk at all.
        const std::vector<std::uint8_t> wcsph = encodeFrame(randomState(9, 6, 3), FrameStats{});
        QCOMPARE(chunkOffset(wcsph, "PSOL"), wcsph.size());
    }

    void corruptPressureSolveChunkDetected() {
        SimulationState state = randomState(9, 6, 3);
        state.warmStart.divergence.assign(6, 1.0f);
        state.warmStart.density.assign(6, 2.0f);
        std::vector<std::uint8_t> bytes = encodeFrame(state, FrameStats{});
        // Seven values claimed for six particles.
        put<std::uint64_t>(bytes, chunkOffset(bytes, "PSOL") + 12, 7);
        resealFrame(bytes);
        const QString message = corruptMessage(bytes);
        QVERIFY2(message.contains("chunk PSOL holds 7 warm-start values") &&
                     message.contains("for 6 particles"),
                 qPrintable(message));
    }

    void framesWithoutSurroundingsReadAsUnmeasured() {
        SimulationState state = randomState(9, 4, 3);
        state.bubbles = twoBubbles();
        const std::vector<std::uint8_t> bytes = encodeFrame(state, FrameStats{});
        const FrameData older = decodeFrame(withoutChunk(bytes, lastChunkOffset(bytes)), kPath);
        QCOMPARE(older.state.bubbles.size(), std::size_t(2));
        QVERIFY(!older.state.bubbles[1].surroundings.measured);
        QCOMPARE(older.state.bubbles[1].radius, 0.03);
    }

    void corruptBubbleChunkDetected() {
        SimulationState state = randomState(9, 4, 3);
        state.bubbles = twoBubbles();
        std::vector<std::uint8_t> bytes = encodeFrame(state, FrameStats{});
        put<std::uint32_t>(bytes, chunkOffset(bytes, "BUBL") + 12, 3); // count says 3, holds 2
        resealFrame(bytes);
        const QString message = corruptMessage(bytes);
        QVERIFY2(message.contains("chunk BUBL is 384 bytes, expected 536 for 3 bubbles"),
                 qPrintable(message));
    }

    void corruptSurroundingsChunkDetected() {
        SimulationState state = randomState(9, 4, 3);
        state.bubbles = twoBubbles();
        std::vector<std::uint8_t> bytes = encodeFrame(state, FrameStats{});
        put<std::uint32_t>(bytes, lastChunkOffset(bytes) + 12, 3); // count says 3, holds 2
        resealFrame(bytes);
        QString message = corruptMessage(bytes);
        QVERIFY2(message.contains("chunk BSUR is 88 bytes, expected 130 for 3 bubbles"),
                 qPrintable(message));
        // A whole chunk for one bubble fewer than BUBL holds does not pass either.
        state.bubbles.pop_back();
        const std::vector<std::uint8_t> oneBubble = encodeFrame(state, FrameStats{});
        const std::size_t at = lastChunkOffset(oneBubble);
        state.bubbles = twoBubbles();
        std::vector<std::uint8_t> mixed = encodeFrame(state, FrameStats{});
        mixed = withoutChunk(mixed, lastChunkOffset(mixed));
        mixed.insert(mixed.end(), oneBubble.begin() + std::ptrdiff_t(at), oneBubble.end());
        resealFrame(mixed);
        message = corruptMessage(mixed);
        QVERIFY2(message.contains("chunk BSUR describes 1 bubbles but chunk BUBL holds 2"),
                 qPrintable(message));
    }

    void headerLayoutIsDocumented() {
        const std::vector<std::uint8_t> bytes = encodeFrame(randomState(12, 2, 7), FrameStats{});
        QCOMPARE(std::memcmp(bytes.data(), "ATF\0", 4), 0);
        std::uint32_t version = 0, headerSize = 0;
        std::int32_t frame = 0;
        std::uint64_t payload = 0;
        std::memcpy(&version, bytes.data() + 4, 4);
        std::memcpy(&headerSize, bytes.data() + 8, 4);
        std::memcpy(&frame, bytes.data() + 12, 4);
        std::memcpy(&payload, bytes.data() + 16, 8);
        QCOMPARE(version, kFrameFormatVersion);
        QCOMPARE(headerSize, kFrameHeaderSize);
        QCOMPARE(frame, 12);
        QCOMPARE(payload, bytes.size() - kFrameHeaderSize);
        // zlib's CRC-32 of "123456789" is the standard check value.
        QCOMPARE(computeCrc32("123456789", 9), 0xCBF43926u);
    }
};

AIRTRAP_TEST_APPLESS(TestFrameFile)
#include "TestFrameFile.moc"
