# The import's preview scene: a camera framing the bake, a sun, a sky, a floor to see the water
# against, and Cycles settings that render a clear frame in seconds on a CPU, so that pressing
# F12 after the import shows the bake (docs/BLENDER.md "Preview scene").
import math
from array import array

import bpy
from mathutils import Vector

from . import materials

VIEW_AZIMUTH = math.radians(-35.0)  # from the front (−y), turned towards −x
VIEW_ELEVATION = math.radians(35.0)
SUN_AZIMUTH = math.radians(-120.0)
SUN_ELEVATION = math.radians(50.0)
LENS_MM = 35.0
FRAME_MARGIN = 1.15
# Marks the collection an import's preview lives in.
PREVIEW_TAG = "airtrap_preview"
_DATA_BLOCKS = {"Camera": "cameras", "SunLight": "lights", "PointLight": "lights",
                "Mesh": "meshes"}
# Blender's startup scene: a 2 m cube at the origin, a point light and a camera. The cube would
# stand over the tank, hiding the water from the preview's camera.
STARTUP_OBJECTS = {"Cube": 'MESH', "Light": 'LIGHT', "Camera": 'CAMERA'}


def _bounds(collections):
    """The smallest box holding every vertex of the meshes in `collections` (their frame
    objects, in world space, which is their mesh space), or None when they are empty."""
    low, high = [math.inf] * 3, [-math.inf] * 3
    for collection in collections:
        for obj in collection.all_objects:
            if obj.type != 'MESH' or not obj.data.vertices:
                continue
            coordinates = array('f', [0.0]) * (3 * len(obj.data.vertices))
            obj.data.vertices.foreach_get("co", coordinates)
            for axis in range(3):
                values = coordinates[axis::3]
                low[axis] = min(low[axis], min(values))
                high[axis] = max(high[axis], max(values))
    return None if low[0] == math.inf else (Vector(low), Vector(high))


def _direction(azimuth, elevation):
    return Vector((math.sin(azimuth) * math.cos(elevation),
                   -math.cos(azimuth) * math.cos(elevation), math.sin(elevation)))


def _framing_distance(low, high, view, camera_data, aspect):
    """How far from the box's centre along `view` the camera sees all eight corners."""
    forward = -view
    right = forward.cross(Vector((0.0, 0.0, 1.0))).normalized()
    up = right.cross(forward)
    half_width = camera_data.sensor_width / 2.0 / camera_data.lens
    half_height = half_width / aspect
    centre = (low + high) / 2.0
    distance = 0.0
    for corner in ((x, y, z) for x in (low.x, high.x) for y in (low.y, high.y)
                   for z in (low.z, high.z)):
        offset = Vector(corner) - centre
        towards_camera = offset.dot(view)
        distance = max(distance,
                       towards_camera + abs(offset.dot(right)) / half_width,
                       towards_camera + abs(offset.dot(up)) / half_height)
    return distance * FRAME_MARGIN


def _camera(scene, collection, low, high):
    data = bpy.data.cameras.new("Airtrap camera")
    data.lens = LENS_MM
    data.clip_start = 0.01
    camera = bpy.data.objects.new("Airtrap camera", data)
    view = _direction(VIEW_AZIMUTH, VIEW_ELEVATION)
    aspect = scene.render.resolution_x / scene.render.resolution_y
    distance = _framing_distance(low, high, view, data, aspect)
    camera.location = (low + high) / 2.0 + view * distance
    camera.rotation_euler = (-view).to_track_quat('-Z', 'Y').to_euler()
    data.clip_end = max(100.0, 4.0 * distance)
    collection.objects.link(camera)
    scene.camera = camera
    return camera


def _sun(collection):
    data = bpy.data.lights.new("Airtrap sun", 'SUN')
    data.energy = 4.0
    data.angle = math.radians(3.0)
    sun = bpy.data.objects.new("Airtrap sun", data)
    sun.rotation_euler = (-_direction(SUN_AZIMUTH, SUN_ELEVATION)).to_track_quat(
        '-Z', 'Y').to_euler()
    collection.objects.link(sun)
    return sun


def _sky(scene):
    """A clear daylight sky lighting the scene softly; the sun lamp gives the shadows."""
    world = bpy.data.worlds.get("Airtrap sky")
    if world is not None:
        scene.world = world
        return
    world = bpy.data.worlds.new("Airtrap sky")
    world.use_nodes = True
    nodes = world.node_tree.nodes
    sky = nodes.new('ShaderNodeTexSky')
    sky.sky_type = 'NISHITA'
    sky.sun_disc = False
    sky.sun_elevation = SUN_ELEVATION
    sky.sun_rotation = SUN_AZIMUTH
    background = nodes.get("Background")
    background.inputs["Strength"].default_value = 0.35
    world.node_tree.links.new(sky.outputs[0], background.inputs["Color"])
    scene.world = world


def _floor(collection, low, high):
    """A checkered floor at the bottom of the box: refraction through the water shows on it."""
    extent = max((high - low).length, 0.1)
    half = 6.0 * extent
    mesh = bpy.data.meshes.new("Airtrap floor")
    mesh.from_pydata([(-half, -half, 0.0), (half, -half, 0.0), (half, half, 0.0),
                      (-half, half, 0.0)], [], [(0, 1, 2, 3)])
    mesh.materials.append(materials.floor_material(extent / 8.0))
    floor = bpy.data.objects.new("Airtrap floor", mesh)
    centre = (low + high) / 2.0
    floor.location = (centre.x, centre.y, low.z)
    collection.objects.link(floor)
    return floor


def _tank(collection, low, high):
    """The container's four walls as thin glass, so the water meets something at its sides (the
    free-surface mesh has no polygons along the walls)."""
    x0, y0, z0 = low
    x1, y1, z1 = high
    corners = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
               (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    walls = [(0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    mesh = bpy.data.meshes.new("Airtrap tank")
    mesh.from_pydata(corners, [], walls)
    mesh.materials.append(materials.thin_glass_material())
    tank = bpy.data.objects.new("Airtrap tank", mesh)
    collection.objects.link(tank)
    return tank


def _render_settings(scene):
    """Cycles on the CPU, few samples and enough light bounces for water with bubbles inside.
    No denoiser: Debian's Blender is built without OpenImageDenoise."""
    scene.render.engine = 'CYCLES'
    cycles = scene.cycles
    cycles.device = 'CPU'
    cycles.samples = 32
    cycles.use_adaptive_sampling = True
    cycles.adaptive_threshold = 0.05
    cycles.use_denoising = False
    cycles.use_preview_denoising = False
    cycles.max_bounces = 12
    cycles.transmission_bounces = 12
    cycles.glossy_bounces = 4
    cycles.diffuse_bounces = 2
    cycles.transparent_max_bounces = 8
    cycles.caustics_reflective = False
    cycles.caustics_refractive = False
    cycles.blur_glossy = 1.0
    scene.render.resolution_x = 800
    scene.render.resolution_y = 450
    scene.render.resolution_percentage = 100


def _is_startup_cube(obj):
    return (len(obj.data.vertices) == 8 and obj.location.length < 1e-6
            and all(abs(size - 2.0) < 1e-6 for size in obj.dimensions)
            and obj.rotation_euler.to_quaternion().angle < 1e-6)


def untouched_startup_objects(scene):
    """Blender's startup cube, light and camera when the scene holds exactly them and the cube
    has not been moved, turned, scaled or edited; otherwise none: a scene someone has worked in
    keeps all it holds."""
    objects = list(scene.objects)
    if sorted(obj.name for obj in objects) != sorted(STARTUP_OBJECTS):
        return []
    if any(obj.type != STARTUP_OBJECTS[obj.name] for obj in objects):
        return []
    cube = scene.objects["Cube"]
    return objects if _is_startup_cube(cube) else []


def _remove_with_data(obj):
    data = obj.data
    material_list = list(data.materials) if hasattr(data, "materials") else []
    bpy.data.objects.remove(obj)
    blocks = _DATA_BLOCKS.get(type(data).__name__)
    if blocks is not None and data.users == 0:
        getattr(bpy.data, blocks).remove(data)
    for material in material_list:
        if material is not None and material.users == 0:
            bpy.data.materials.remove(material)


def remove_startup_objects(objects):
    """Removes the startup objects found by untouched_startup_objects (before the import)."""
    for obj in objects:
        _remove_with_data(obj)


def _remove_earlier_previews():
    """An earlier import's preview goes, with its data: a second import is framed and lit once,
    by its own camera and sun."""
    for collection in [c for c in bpy.data.collections if c.get(PREVIEW_TAG)]:
        for obj in list(collection.objects):
            _remove_with_data(obj)
        bpy.data.collections.remove(collection)


def _union(a, b):
    if a is None or b is None:
        return a or b
    return (Vector(tuple(map(min, a[0], b[0]))), Vector(tuple(map(max, a[1], b[1]))))


def set_up(scene, bake_collection, frame_collections, container):
    """Adds the preview scene in a collection "Preview" inside `bake_collection`: the camera
    frames the tank (`container`, ((x, y, z) low, (x, y, z) high) or None) up to the height the
    meshes of `frame_collections` reach, and those meshes. Nothing when there is neither."""
    tank = None if container is None else (Vector(container[0]), Vector(container[1]))
    shown = _bounds(frame_collections)
    framed = tank
    if tank is not None and shown is not None:
        # The tank's floor and whatever the sequences reach: not the empty headroom above.
        framed = (tank[0], Vector((tank[1].x, tank[1].y, min(tank[1].z, shown[1].z))))
    bounds = _union(framed, shown)
    if bounds is None:
        return None
    low, high = bounds
    _remove_earlier_previews()
    preview = bpy.data.collections.new("Preview")
    preview[PREVIEW_TAG] = True
    bake_collection.children.link(preview)
    _render_settings(scene)
    _camera(scene, preview, low, high)
    _sun(preview)
    _sky(scene)
    _floor(preview, tank[0] if tank else low, tank[1] if tank else high)
    if tank is not None:
        _tank(preview, *tank)
    return preview
