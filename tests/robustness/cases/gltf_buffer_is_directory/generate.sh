mkdir -p buffers
