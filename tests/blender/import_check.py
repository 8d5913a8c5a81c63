# Imports ramus GLBs into Blender (Debian's blender, its bundled glTF importer) and checks that
# they arrive as a user would want them: run as
#
#   blender -b --factory-startup --python tests/blender/import_check.py -- FILE.glb ...
#
# Every file: imports without an exception, one Blender object per glTF node with a mesh, the
# glTF's triangle count. Skinned files: one armature with one bone per joint, named like the
# joint nodes, every mesh deformed by it (Armature modifier). ramus skeletons (joints with a
# "kind" in their extras): every bone mesh is its own object bound to its own bone alone; rotating one bone in pose mode
# moves its mesh and the meshes of its descendants, and leaves the other meshes where they were.
# Prints one line per file and exits 1 when a check fails.
import json
import math
import struct
import sys

import bpy
import numpy
from mathutils import Euler

# Debian 12's Blender 3.4 glTF importer still uses numpy.bool, which Debian's numpy 1.24 no longer
# has; the alias meant the builtin bool.
if 'bool' not in vars(numpy):
    numpy.bool = bool

failures = 0


def gltf_json(path):
    with open(path, 'rb') as f:
        data = f.read()
    length = struct.unpack_from('<I', data, 12)[0]
    return json.loads(data[20:20 + length])


def world_vertices(obj, depsgraph):
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    points = [evaluated.matrix_world @ v.co for v in mesh.vertices]
    evaluated.to_mesh_clear()
    return points


def max_shift(before, after):
    return max((a - b).length for a, b in zip(before, after)) if before else 0.0


def check(ok, what, path):
    global failures
    if not ok:
        failures += 1
        print(f'FAIL {path}: {what}')
    return ok


def triangles(doc):
    count = 0
    for node in doc.get('nodes', []):
        if 'mesh' not in node:
            continue
        for prim in doc['meshes'][node['mesh']]['primitives']:
            count += doc['accessors'][prim['indices']]['count'] // 3
    return count


def check_skeleton(path, doc, meshes):
    skin = doc['skins'][0]
    joint_names = [doc['nodes'][j]['name'] for j in skin['joints']]
    armatures = [o for o in bpy.data.objects if o.type == 'ARMATURE']
    if not check(len(armatures) == 1, f'{len(armatures)} armatures, expected 1', path):
        return
    arm = armatures[0]
    bones = arm.data.bones
    check(len(bones) == len(joint_names), f'{len(bones)} bones for {len(joint_names)} joints', path)
    check(sorted(b.name for b in bones) == sorted(joint_names), 'bone names differ from joints', path)
    for obj in meshes:
        mods = [m for m in obj.modifiers if m.type == 'ARMATURE' and m.object == arm]
        check(len(mods) == 1, f'{obj.name}: not deformed by the armature', path)
        groups = [g.name for g in obj.vertex_groups]
        check(len(groups) >= 1, f'{obj.name}: no vertex group', path)
    if not all('kind' in doc['nodes'][j].get('extras', {}) for j in skin['joints']):
        print(f'ok   {path}: {len(meshes)} mesh objects, {len(bones)} bones (a skin, not a skeleton)')
        return
    # A ramus skeleton: one rigidly bound mesh per bone. Pose test: a bone halfway down the
    # hierarchy that has a mesh of its own.
    by_bone = {}
    for obj in meshes:
        weighted = {g.index: g.name for g in obj.vertex_groups}
        used = set()
        for v in obj.data.vertices:
            for g in v.groups:
                if g.weight > 0:
                    used.add(weighted[g.group])
        check(len(used) == 1, f'{obj.name}: bound to {len(used)} bones, expected 1', path)
        if len(used) == 1:
            by_bone[used.pop()] = obj
    candidates = [b for b in bones if b.name in by_bone and b.parent is not None and b.children]
    if not check(candidates, 'no bone with a mesh and children to pose', path):
        return
    bone = candidates[len(candidates) // 2]
    moved = {bone.name} | {c.name for c in bone.children_recursive}
    depsgraph = bpy.context.evaluated_depsgraph_get()
    before = {name: world_vertices(obj, depsgraph) for name, obj in by_bone.items()}
    pose_bone = arm.pose.bones[bone.name]
    pose_bone.rotation_mode = 'XYZ'
    pose_bone.rotation_euler = Euler((math.radians(40), 0, math.radians(25)))
    bpy.context.view_layer.update()
    depsgraph = bpy.context.evaluated_depsgraph_get()
    size = max(max(p.length for p in pts) for pts in before.values() if pts) or 1.0
    for name, obj in by_bone.items():
        shift = max_shift(before[name], world_vertices(obj, depsgraph))
        if name in moved and name != bone.name:
            continue  # descendants move too, but a child sitting on the axis may barely move
        if name == bone.name:
            check(shift > 1e-4 * size, f'posing {bone.name} did not move its mesh', path)
        else:
            check(shift < 1e-5 * size, f'posing {bone.name} moved {name} by {shift:.3g}', path)
    print(f'ok   {path}: {len(meshes)} mesh objects, {len(bones)} bones, posed {bone.name}')


def check_file(path):
    doc = gltf_json(path)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    try:
        bpy.ops.import_scene.gltf(filepath=path)
    except Exception as e:  # noqa: BLE001 - any importer error is a failure
        check(False, f'import failed: {e}', path)
        return
    meshes = [o for o in bpy.data.objects if o.type == 'MESH']
    expected = sum(1 for n in doc.get('nodes', []) if 'mesh' in n)
    check(len(meshes) == expected, f'{len(meshes)} mesh objects, expected {expected}', path)
    tris = 0
    for obj in meshes:
        obj.data.calc_loop_triangles()
        tris += len(obj.data.loop_triangles)
    check(tris == triangles(doc), f'{tris} triangles, expected {triangles(doc)}', path)
    if doc.get('skins'):
        check_skeleton(path, doc, meshes)
    else:
        print(f'ok   {path}: {len(meshes)} mesh objects, {tris} triangles')


files = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else []
for f in files:
    check_file(f)
print(f'blender import: {len(files)} files, {failures} failures')
sys.exit(1 if failures or not files else 0)
