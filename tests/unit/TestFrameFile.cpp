// One frame file: exact round trip, and every kind of damage detected with a clear message.
#include "cache/FrameFile.h"
#include "unit/CacheTestData.h"

#include <QtTest/QtTest>
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

QTEST_APPLESS_MAIN(TestFrameFile)
#include "TestFrameFile.moc"
