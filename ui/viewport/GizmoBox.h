#pragma once
// One gizmo of the scene as the viewport draws and picks it: a box, or for an emitter the outline
// of its nozzle (a disc or a rectangle) with an arrow along its jet, picked by the box around them.
#include "document/SceneItem.h"

#include <QVector3D>
#include <vector>

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
    //! An emitter's nozzle exit as a closed loop of points, m; empty for the other kinds.
    std::vector<QVector3D> outline{};
    QVector3D centre{}; //!< an emitter's exit centre, m
    QVector3D jet{};    //!< an emitter's arrow: from the centre along the jet, m
};

} // namespace airtrap
