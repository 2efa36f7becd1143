"""Reads map files for UploadMap, detecting the format from the extension as the CLI does."""

from __future__ import annotations

import os
import re

from ._proto.swarmplan.v1 import maps_pb2

# Extension -> server format name (core/map/io/map_io.cc GuessMapFormat).
FORMATS_BY_EXTENSION = {
    ".yaml": "ros-yaml-pgm",
    ".yml": "ros-yaml-pgm",
    ".map": "movingai",
    ".txt": "ascii",
    ".ascii": "ascii",
    ".pgm": "pgm",
    ".png": "png",
    ".geojson": "geojson",
    ".json": "shapes-json",
    ".asc": "terrain-asc",
    ".csv": "terrain-csv",
}


def guess_format(path: str) -> str:
    """The format a file name suggests, or "" when the extension is not known."""
    return FORMATS_BY_EXTENSION.get(os.path.splitext(path)[1].lower(), "")


def ros_image_path(yaml_path: str, content: bytes) -> str:
    """The image a ROS map_server YAML names, resolved against the YAML's folder."""
    match = re.search(r"^image\s*:\s*(.*?)\s*$", content.decode("utf-8", "replace"),
                      re.MULTILINE)
    value = match.group(1) if match else ""
    if value[:1] in ("'", '"'):
        value = value[1:value.index(value[0], 1)] if value.count(value[0]) >= 2 else value[1:]
    else:
        value = re.sub(r"\s+#.*$", "", value)
    if not value:
        raise ValueError("%s: image: missing (the image file name)" % yaml_path)
    if os.path.isabs(value):
        return value
    return os.path.join(os.path.dirname(yaml_path), value)


def read_map_files(path: str, format: str | None = None) -> maps_pb2.MapFiles:
    """Reads `path` (and for ros-yaml-pgm the image it names) into a MapFiles message."""
    resolved = format or guess_format(path)
    if not resolved:
        known = sorted(set(FORMATS_BY_EXTENSION.values()) | {"terrain-pgm"})
        raise ValueError("%s: cannot tell the map format from the extension; pass format= "
                         "(one of %s)" % (path, ", ".join(known)))
    with open(path, "rb") as f:
        content = f.read()
    files = maps_pb2.MapFiles(format=resolved)
    files.files.add(name=os.path.basename(path), content=content)
    if resolved == "ros-yaml-pgm":
        image_path = ros_image_path(path, content)
        with open(image_path, "rb") as f:
            files.files.add(name=os.path.basename(image_path), content=f.read())
    return files
