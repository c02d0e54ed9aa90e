# The materials the import gives its objects.
import bpy

WATER_IOR = 1.333


def _material(name, build):
    """The material `name`, made by `build(material)` (its nodes in use) the first time."""
    material = bpy.data.materials.get(name)
    if material is None:
        material = bpy.data.materials.new(name)
        material.use_nodes = True
        build(material)
    return material


def water_material():
    """Clear water: Principled BSDF, full transmission, IOR 1.333, no roughness."""
    def build(material):
        bsdf = material.node_tree.nodes.get("Principled BSDF")
        bsdf.inputs["Base Color"].default_value = (0.8, 0.93, 1.0, 1.0)
        bsdf.inputs["Transmission"].default_value = 1.0
        bsdf.inputs["IOR"].default_value = WATER_IOR
        bsdf.inputs["Roughness"].default_value = 0.0
        _clear_to_shadow_rays(material, bsdf.outputs[0])
    return _material("Airtrap water", build)


def _clear_to_shadow_rays(material, surface):
    """Lets shadow rays through `surface` (a refracting one): with caustics off, as quick renders
    have them, light reaches what lies under water only through such rays, and a refracting
    surface would otherwise shade the whole pool black. A common stand-in for caustics."""
    tree = material.node_tree
    path = tree.nodes.new('ShaderNodeLightPath')
    clear = tree.nodes.new('ShaderNodeBsdfTransparent')
    mix = tree.nodes.new('ShaderNodeMixShader')
    tree.links.new(path.outputs["Is Shadow Ray"], mix.inputs[0])
    tree.links.new(surface, mix.inputs[1])
    tree.links.new(clear.outputs[0], mix.inputs[2])
    tree.links.new(mix.outputs[0], tree.nodes.get("Material Output").inputs["Surface"])


def air_material():
    """An air bubble in water: glass of relative IOR 1/1.333. Cycles does not track which medium
    a ray is in, and a bubble always sits in water, so its surface bends light as air seen from
    water does (total internal reflection at grazing angles gives bubbles their bright rims)."""
    def build(material):
        nodes = material.node_tree.nodes
        nodes.remove(nodes.get("Principled BSDF"))
        glass = nodes.new('ShaderNodeBsdfGlass')
        glass.inputs["IOR"].default_value = 1.0 / WATER_IOR
        glass.inputs["Roughness"].default_value = 0.0
        _clear_to_shadow_rays(material, glass.outputs[0])
    return _material("Airtrap air bubble", build)


def body_material():
    """The bodies and obstacles: a plain light grey, matte plastic."""
    def build(material):
        bsdf = material.node_tree.nodes.get("Principled BSDF")
        bsdf.inputs["Base Color"].default_value = (0.6, 0.6, 0.58, 1.0)
        bsdf.inputs["Roughness"].default_value = 0.5
        material.diffuse_color = (0.6, 0.6, 0.58, 1.0)
    return _material("Airtrap body", build)


def volume_material():
    """Water as a light blue fog: Principled Volume reading the `density` grid (its default
    density attribute), thin enough that the surface mesh stays the water's look."""
    def build(material):
        nodes = material.node_tree.nodes
        nodes.remove(nodes.get("Principled BSDF"))
        fog = nodes.new('ShaderNodeVolumePrincipled')
        fog.inputs["Color"].default_value = (0.55, 0.8, 1.0, 1.0)
        fog.inputs["Density"].default_value = 2.0
        material.node_tree.links.new(fog.outputs[0],
                                     nodes.get("Material Output").inputs["Volume"])
    return _material("Airtrap water volume", build)


def floor_material(square):
    """A matte checker of squares `square` metres wide, in object space (the floor's size does
    not matter)."""
    material = bpy.data.materials.new("Airtrap floor")
    material.use_nodes = True
    tree = material.node_tree
    checker = tree.nodes.new('ShaderNodeTexChecker')
    checker.inputs["Scale"].default_value = 1.0 / square
    checker.inputs["Color1"].default_value = (0.6, 0.6, 0.58, 1.0)
    checker.inputs["Color2"].default_value = (0.4, 0.4, 0.4, 1.0)
    coordinates = tree.nodes.new('ShaderNodeTexCoord')
    tree.links.new(coordinates.outputs["Object"], checker.inputs["Vector"])
    bsdf = tree.nodes.get("Principled BSDF")
    bsdf.inputs["Roughness"].default_value = 0.6
    tree.links.new(checker.outputs["Color"], bsdf.inputs["Base Color"])
    return material


def _pane_fresnel(tree):
    """Fresnel reflectance of glass (IOR 1.5) the same from both sides of a face. Cycles'
    Fresnel node inverts the IOR on a back face, and seen from inside the tank the walls would
    then mirror everything past 42°, as a glass block does; a back face gets 1/1.5, which the
    node turns back into 1.5."""
    backfacing = tree.nodes.new('ShaderNodeNewGeometry').outputs["Backfacing"]
    ior = tree.nodes.new('ShaderNodeMath')
    ior.operation = 'MULTIPLY_ADD'
    tree.links.new(backfacing, ior.inputs[0])
    ior.inputs[1].default_value = 1.0 / 1.5 - 1.5
    ior.inputs[2].default_value = 1.5
    fresnel = tree.nodes.new('ShaderNodeFresnel')
    tree.links.new(ior.outputs[0], fresnel.inputs["IOR"])
    return fresnel.outputs[0]


def thin_glass_material():
    """A pane of glass of no thickness: light passes straight through (a zero-thickness wall
    cannot refract the way a slab does, which shifts rays back parallel anyway) and the
    surface reflects by Fresnel at IOR 1.5."""
    def build(material):
        tree = material.node_tree
        nodes = tree.nodes
        nodes.remove(nodes.get("Principled BSDF"))
        clear = nodes.new('ShaderNodeBsdfTransparent')
        shine = nodes.new('ShaderNodeBsdfGlossy')
        shine.inputs["Roughness"].default_value = 0.0
        mix = nodes.new('ShaderNodeMixShader')
        tree.links.new(_pane_fresnel(tree), mix.inputs[0])
        tree.links.new(clear.outputs[0], mix.inputs[1])
        tree.links.new(shine.outputs[0], mix.inputs[2])
        tree.links.new(mix.outputs[0], nodes.get("Material Output").inputs["Surface"])
    return _material("Airtrap thin glass", build)
