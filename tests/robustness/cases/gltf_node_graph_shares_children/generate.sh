# 60 nodes, each with the next as both of its children: 2^60 paths through a small graph.
python3 - <<'PY'
import json
n = 60
nodes = [{"children": [i + 1, i + 1]} for i in range(n)] + [{"mesh": 0}]
model = {"asset": {"version": "2.0"},
         "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
         "bufferViews": [{"buffer": 0, "byteLength": 36}],
         "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
         "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
         "nodes": nodes, "scenes": [{"nodes": [0]}]}
json.dump(model, open("model.gltf", "w"))
PY
