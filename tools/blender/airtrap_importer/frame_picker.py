# A sequence that plays without Python: each frame's data is an object in a hidden collection
# (one per frame, in frame order), and the object the user sees has a Geometry Nodes modifier
# that keeps, from that collection, only the child of the scene's current frame. Blender then
# plays and renders the sequence by itself: a saved file renders in a fresh Blender without this
# add-on (Debian's Blender 3.4 has no Alembic or USD to bake a changing mesh into).
import bpy


def frame_object_name(stem, frame):
    """Six digits, so that the collection's children sort in frame order up to frame 999999."""
    return "%s_frame_%06d" % (stem, frame)


def _new_node(tree, kind, location):
    node = tree.nodes.new(kind)
    node.location = location
    return node


def frame_picker_group(name, frames, first_frame, spheres_material=None):
    """A node group whose output is the realised geometry of `frames`' child for the current
    frame (nothing outside the sequence), where `frames` holds one object per frame from
    `first_frame` on. With `spheres_material`, the child's points become spheres of radius
    `pscale` in that material."""
    tree = bpy.data.node_groups.new(name, 'GeometryNodeTree')
    tree.inputs.new('NodeSocketGeometry', "Geometry")
    tree.outputs.new('NodeSocketGeometry', "Geometry")
    links = tree.links
    output = _new_node(tree, 'NodeGroupOutput', (900, 0))
    info = _new_node(tree, 'GeometryNodeCollectionInfo', (0, 0))
    info.transform_space = 'RELATIVE'
    info.inputs['Collection'].default_value = frames
    info.inputs['Separate Children'].default_value = True
    info.inputs['Reset Children'].default_value = True

    # The child to keep: the current frame minus the first. Outside the sequence no child has
    # that index, so the object shows nothing there, as Blender's own volume sequences do.
    time = _new_node(tree, 'GeometryNodeInputSceneTime', (-400, -200))
    child = _new_node(tree, 'ShaderNodeMath', (-200, -200))
    child.operation = 'SUBTRACT'
    child.inputs[1].default_value = float(first_frame)
    links.new(time.outputs['Frame'], child.inputs[0])
    # Motion blur evaluates the scene a fraction of a frame off: those times keep this frame.
    nearest = _new_node(tree, 'ShaderNodeMath', (0, -200))
    nearest.operation = 'ROUND'
    links.new(child.outputs[0], nearest.inputs[0])

    index = _new_node(tree, 'GeometryNodeInputIndex', (200, -350))
    other = _new_node(tree, 'FunctionNodeCompare', (400, -250))
    other.data_type = 'INT'
    other.operation = 'NOT_EQUAL'
    links.new(index.outputs[0], other.inputs[2])
    links.new(nearest.outputs[0], other.inputs[3])

    drop = _new_node(tree, 'GeometryNodeDeleteGeometry', (400, 0))
    drop.domain = 'INSTANCE'
    links.new(info.outputs[0], drop.inputs['Geometry'])
    links.new(other.outputs[0], drop.inputs['Selection'])
    realise = _new_node(tree, 'GeometryNodeRealizeInstances', (650, 0))
    links.new(drop.outputs[0], realise.inputs[0])
    if spheres_material is None:
        links.new(realise.outputs[0], output.inputs[0])
        return tree
    sphere = _new_node(tree, 'GeometryNodeMeshIcoSphere', (400, 250))
    sphere.inputs['Radius'].default_value = 1.0
    sphere.inputs['Subdivisions'].default_value = 2
    smooth = _new_node(tree, 'GeometryNodeSetShadeSmooth', (550, 250))
    links.new(sphere.outputs['Mesh'], smooth.inputs['Geometry'])
    material = _new_node(tree, 'GeometryNodeSetMaterial', (700, 250))
    material.inputs['Material'].default_value = spheres_material
    links.new(smooth.outputs[0], material.inputs['Geometry'])
    radius = _new_node(tree, 'GeometryNodeInputNamedAttribute', (650, -200))
    radius.data_type = 'FLOAT'
    radius.inputs['Name'].default_value = "pscale"
    instance = _new_node(tree, 'GeometryNodeInstanceOnPoints', (800, 0))
    links.new(realise.outputs[0], instance.inputs['Points'])
    links.new(material.outputs[0], instance.inputs['Instance'])
    # The node has one output per data type, all named "Attribute": the float one is enabled.
    radius_output = next(o for o in radius.outputs if o.enabled and o.type == 'VALUE')
    links.new(radius_output, instance.inputs['Scale'])
    # Realised, every sphere's vertices carry its point's attributes: `velocity`, which Cycles
    # uses for motion blur (instances would not pass it on), and `pscale`.
    spheres = _new_node(tree, 'GeometryNodeRealizeInstances', (1000, 0))
    links.new(instance.outputs[0], spheres.inputs[0])
    output.location = (1200, 0)
    links.new(spheres.outputs[0], output.inputs[0])
    return tree


def hidden_collection(name, parent):
    """A collection for the per-frame objects: neither drawn nor rendered itself."""
    collection = bpy.data.collections.new(name)
    parent.children.link(collection)
    collection.hide_viewport = True
    collection.hide_render = True
    return collection


def picking_object(name, collection, frames, first_frame, group_name, spheres_material=None):
    """A mesh object showing `frames`' child of the current frame, in `collection`."""
    obj = bpy.data.objects.new(name, bpy.data.meshes.new(name))
    collection.objects.link(obj)
    modifier = obj.modifiers.new(group_name, 'NODES')
    modifier.node_group = frame_picker_group(group_name, frames, first_frame, spheres_material)
    return obj
