# The materials the import gives its objects.
import bpy

WATER_IOR = 1.333


def water_material():
    """Clear water: Principled BSDF, full transmission, IOR 1.333, no roughness."""
    material = bpy.data.materials.get("Airtrap water")
    if material is not None:
        return material
    material = bpy.data.materials.new("Airtrap water")
    material.use_nodes = True
    bsdf = material.node_tree.nodes.get("Principled BSDF")
    bsdf.inputs["Base Color"].default_value = (0.8, 0.93, 1.0, 1.0)
    bsdf.inputs["Transmission"].default_value = 1.0
    bsdf.inputs["IOR"].default_value = WATER_IOR
    bsdf.inputs["Roughness"].default_value = 0.0
    return material


def air_material():
    """An air bubble in water: glass of relative IOR 1/1.333. Cycles does not track which medium
    a ray is in, and a bubble always sits in water, so its surface bends light as air seen from
    water does (total internal reflection at grazing angles gives bubbles their bright rims)."""
    material = bpy.data.materials.get("Airtrap air bubble")
    if material is not None:
        return material
    material = bpy.data.materials.new("Airtrap air bubble")
    material.use_nodes = True
    nodes = material.node_tree.nodes
    nodes.remove(nodes.get("Principled BSDF"))
    glass = nodes.new('ShaderNodeBsdfGlass')
    glass.inputs["IOR"].default_value = 1.0 / WATER_IOR
    glass.inputs["Roughness"].default_value = 0.0
    material.node_tree.links.new(glass.outputs[0], nodes.get("Material Output").inputs["Surface"])
    return material
