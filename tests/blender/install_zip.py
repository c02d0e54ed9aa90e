# Run by ctest (label blender) as
#   blender -b --factory-startup --python-exit-code 1 --python install_zip.py -- ADDON_ZIP
# with BLENDER_USER_SCRIPTS pointing into the build tree: the zip that scripts/blender-addon.sh
# makes installs as a user would install it, enables, and adds File > Import > Airtrap bake.
import sys

import addon_utils
import bpy

zip_path = sys.argv[sys.argv.index("--") + 1]
bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
if addon_utils.enable("airtrap_importer", default_set=True) is None:
    print("FAIL: the installed add-on does not enable")
    sys.exit(1)
if not hasattr(bpy.ops.import_scene, "airtrap_bake"):
    print("FAIL: no import_scene.airtrap_bake operator")
    sys.exit(1)
entries = [f.__name__ for f in bpy.types.TOPBAR_MT_file_import._dyn_ui_initialize()]
if "menu_entry" not in entries:
    print("FAIL: File > Import has no Airtrap bake entry: %s" % entries)
    sys.exit(1)
print("PASS")
