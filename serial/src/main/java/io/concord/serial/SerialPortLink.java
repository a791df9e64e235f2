package io.concord.serial;

import com.fazecast.jSerialComm.SerialPort;

import java.nio.file.Files;
import java.nio.file.Path;

/** The board's serial port, open, through jSerialComm. */
final class SerialPortLink implements BoardLink {
    private final SerialPort port;
    private final Path path;

    /** @param path the path the port was opened at: a read after it is gone says the port is gone */
    SerialPortLink(SerialPort port, Path path) {
        this.port = port;
        this.path = path;
    }

    @Override
    public int read(byte[] buf) {
        int n = port.readBytes(buf, buf.length);
        return n < 0 || !Files.exists(path) ? -1 : n;
    }

    @Override
    public boolean write(byte[] frame) {
        return port.writeBytes(frame, frame.length) == frame.length;
    }

    @Override
    public void close() {
        port.closePort();
    }
}
