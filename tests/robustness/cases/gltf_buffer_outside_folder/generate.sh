# A file beside the case's folder, which the model names through '..'.
printf 'secret-outside-content-0123456789abcdef0123' > ../outside.bin
