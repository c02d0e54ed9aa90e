#pragma once
// One box-shaped gizmo of the scene as the viewport draws and picks it.
#include "document/SceneItem.h"

#include <QVector3D>

namespace airtrap {

struct GizmoBox {
    enum class Kind {
        Container,  //!< the tank; picked by its edges, since its inside is where the water is
        FluidBlock, //!< a block of water at t = 0; solid for picking
        Obstacle,   //!< a static box; solid for picking
        Emitter,    //!< the exit of an inflow nozzle, with a little depth along the jet
    };

    Kind kind = Kind::Obstacle;
    SceneItem item; //!< what picking this gizmo selects
    QVector3D min;  //!< m
    QVector3D max;  //!< m
};

} // namespace airtrap
