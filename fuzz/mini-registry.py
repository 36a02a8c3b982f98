#!/usr/bin/env python3
"""Writes the fuzz targets' seed registry: the pinned vk.xml cut down to a few commands
and everything they name (types, enum groups, the versions' and a few extensions'
requires), small enough for the fuzzer to run every pass thousands of times a second.

    python3 fuzz/mini-registry.py vk.xml > fuzz/seeds/registry/mini-vk.xml
"""
import re
import sys
import xml.etree.ElementTree as ET

ROOTS = [
    "vkCreateInstance", "vkDestroyInstance", "vkEnumeratePhysicalDevices",
    "vkCreateDevice", "vkDestroyDevice", "vkGetDeviceQueue", "vkCreateBuffer",
    "vkDestroyBuffer", "vkCreateCommandPool", "vkDestroyCommandPool",
    "vkAllocateCommandBuffers", "vkFreeCommandBuffers", "vkBeginCommandBuffer",
    "vkEndCommandBuffer", "vkCmdFillBuffer", "vkCmdCopyBuffer", "vkQueueSubmit",
    "vkCreateFence", "vkDestroyFence", "vkWaitForFences", "vkCmdSetEvent",
    "vkCreateEvent", "vkDestroyEvent", "vkCmdSetLineWidth",
]
EXTENSIONS = ["VK_KHR_maintenance1", "VK_EXT_line_rasterization", "VK_KHR_synchronization2"]

tree = ET.parse(sys.argv[1])
reg = tree.getroot()
types = {t.get("name") or t.findtext("name"): t for t in reg.find("types")}
commands = {}
for c in reg.find("commands"):
    name = c.get("name") or c.find("proto").findtext("name")
    commands[name] = c

keep_types, keep_cmds = set(), set()


def want_type(name):
    if name in keep_types or name not in types:
        return
    keep_types.add(name)
    t = types[name]
    for attr in ("requires", "parent", "alias", "bitvalues"):
        for n in (t.get(attr) or "").split(","):
            if n:
                want_type(n)
    for n in t.iter("type"):
        want_type(n.text)
    for m in t.findall("member"):
        if m.findtext("type"):
            want_type(m.findtext("type"))


def want_cmd(name):
    if name in keep_cmds or name not in commands:
        return
    keep_cmds.add(name)
    c = commands[name]
    if c.get("alias"):
        want_cmd(c.get("alias"))
    for p in c.iter("type"):
        want_type(p.text)


for name in ROOTS:
    want_cmd(name)
for t in ("VkStructureType", "VkResult", "VkObjectType", "VkBaseInStructure", "VkBaseOutStructure"):
    want_type(t)
# Enum and flag types of the extensions kept, and the bit types of kept flags.
for name, t in list(types.items()):
    if t.get("category") in ("include", "define", "basetype") or t.get("requires") == "vk_platform":
        keep_types.add(name)

# Cut the types: what nothing kept names goes; a struct keeps only kept extenders.
types_el = reg.find("types")
for t in list(types_el):
    name = t.get("name") or t.findtext("name")
    if t.tag == "type" and name not in keep_types:
        types_el.remove(t)
    elif t.get("structextends"):
        ext = [e for e in t.get("structextends").split(",") if e in keep_types]
        if ext:
            t.set("structextends", ",".join(ext))
        else:
            del t.attrib["structextends"]
for c in list(reg.find("commands")):
    name = c.get("name") or c.find("proto").findtext("name")
    if name not in keep_cmds:
        reg.find("commands").remove(c)
for e in list(reg.findall("enums")):
    if e.get("name") != "API Constants" and e.get("name") not in keep_types:
        reg.remove(e)


def cut_requires(block):
    for r in list(block.findall("require")):
        for item in list(r):
            name = item.get("name")
            if item.tag == "type" and name not in keep_types:
                r.remove(item)
            elif item.tag == "command" and name not in keep_cmds:
                r.remove(item)
            elif item.tag == "enum" and item.get("extends") and item.get("extends") not in keep_types:
                r.remove(item)
    for r in list(block.findall("remove")):
        block.remove(r)


for f in reg.findall("feature"):
    cut_requires(f)
exts = reg.find("extensions")
for x in list(exts):
    if x.get("name") in EXTENSIONS:
        cut_requires(x)
        # What they depend on is not kept.
        for attr in ("depends", "requires", "requiresCore"):
            x.attrib.pop(attr, None)
    else:
        exts.remove(x)
for tag in ("formats", "sync", "spirvextensions", "spirvcapabilities", "platforms", "tags"):
    for el in reg.findall(tag):
        if tag in ("platforms", "tags"):
            continue
        reg.remove(el)
for c in list(reg):
    if c.tag == "comment":
        reg.remove(c)
ET.indent(tree, "    ")
sys.stdout.write('<?xml version="1.0" encoding="UTF-8"?>\n')
sys.stdout.write(ET.tostring(reg, encoding="unicode"))
sys.stdout.write("\n")
