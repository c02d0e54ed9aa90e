#pragma once
// The 104-byte record of a rigid body's state in frame files (chunks BODY and BUBL): position,
// orientation w x y z, linear and angular velocity, 13 f64 in all.
#include "cache/ByteReader.h"
#include "cache/ByteWriter.h"
#include "rigid/RigidBodyState.h"

namespace airtrap {

struct RigidBodyRecord {
    static constexpr std::size_t kSize = 13 * sizeof(double);

    static void write(ByteWriter& out, const RigidBodyState& body) {
        writeVec3(out, body.position);
        out.f64(body.orientation.w()); // w first, as `info --json` prints it
        out.f64(body.orientation.x());
        out.f64(body.orientation.y());
        out.f64(body.orientation.z());
        writeVec3(out, body.linearVelocity);
        writeVec3(out, body.angularVelocity);
    }

    static RigidBodyState read(ByteReader& in) {
        RigidBodyState body;
        body.position = readVec3(in);
        const double w = in.f64();
        const Vec3d xyz = readVec3(in);
        body.orientation = Quatd(w, xyz.x(), xyz.y(), xyz.z());
        body.linearVelocity = readVec3(in);
        body.angularVelocity = readVec3(in);
        return body;
    }

private:
    static void writeVec3(ByteWriter& out, const Vec3d& v) {
        out.f64(v.x());
        out.f64(v.y());
        out.f64(v.z());
    }
    static Vec3d readVec3(ByteReader& in) {
        const double x = in.f64();
        const double y = in.f64();
        const double z = in.f64();
        return {x, y, z};
    }
};

} // namespace airtrap
