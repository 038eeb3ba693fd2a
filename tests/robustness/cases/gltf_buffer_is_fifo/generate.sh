mkfifo buffer.bin
