mkdir -p sub
echo "return 1" > secret.lua
ln -s .. sub/up
echo "local s = require(\"up.secret\")" > sub/scene.lua
