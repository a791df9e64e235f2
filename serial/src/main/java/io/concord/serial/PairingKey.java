package io.concord.serial;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HexFormat;

/**
 * The key a host and a chair's board are paired with (docs/chair-protocol.md, the MAC): 16 bytes
 * or more, read from a file. A file of hexadecimal digits alone (spaces and line ends ignored) is
 * read as hex, so it needs 32 digits or more; any other file is taken as the raw bytes of the key.
 */
public final class PairingKey {
    /** The shortest key taken. */
    public static final int MIN_BYTES = 16;

    private PairingKey() {
    }

    /**
     * Reads a key file.
     *
     * @throws IllegalArgumentException if the file cannot be read or holds fewer than 16 bytes (the message says which)
     */
    public static byte[] read(Path file) {
        byte[] raw;
        try {
            raw = Files.readAllBytes(file);
        } catch (java.nio.file.NoSuchFileException e) {
            throw new IllegalArgumentException("there is no pairing key file " + file
                    + " (a file of 32 hex digits or more, or of 16 raw bytes or more; the board must hold the same key)");
        } catch (IOException e) {
            throw new IllegalArgumentException("cannot read the pairing key " + file + ": " + e
                    + " (a file of 32 hex digits or more, or of 16 raw bytes or more; the board must hold the same key)");
        }
        String text = new String(raw, StandardCharsets.US_ASCII).replaceAll("\\s+", "");
        byte[] key = raw;
        if (!text.isEmpty() && text.length() % 2 == 0 && text.matches("[0-9a-fA-F]+")) {
            key = HexFormat.of().parseHex(text);
        }
        if (key.length < MIN_BYTES) {
            throw new IllegalArgumentException("the pairing key " + file + " holds " + key.length + " bytes; it needs "
                    + MIN_BYTES + " or more (32 hex digits or more, or raw bytes)");
        }
        return key;
    }
}
