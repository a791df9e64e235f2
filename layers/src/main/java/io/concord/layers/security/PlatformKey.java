package io.concord.layers.security;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.Set;

/**
 * The pre-shared platform key: 256 bits every agent of a platform holds. With no key configured,
 * one is created once per user in {@code ~/.concord/platform.key} (mode 0600, 64 hex digits) and
 * shared by that user's agents on the host, as the Erlang cookie is; across hosts the user copies
 * that file or names one in the configuration. Problems are reported at start, with what to do.
 */
public final class PlatformKey {
    /** Overrides the directory of the default key file (for tests and sandboxes). */
    public static final String HOME_PROPERTY = "concord.home";

    private final byte[] key;
    private final String origin;

    private PlatformKey(byte[] key, String origin) {
        this.key = key;
        this.origin = origin;
    }

    /** A key given in code, as 64 hex digits. */
    public static PlatformKey ofHex(String hex) {
        return new PlatformKey(parse(hex, "the key given in code"), "given in code");
    }

    /** A key given in code, as 32 bytes. */
    public static PlatformKey of(byte[] key) {
        if (key.length != 32) {
            throw new IllegalArgumentException("a platform key has 32 bytes (256 bits), got " + key.length);
        }
        return new PlatformKey(key.clone(), "given in code");
    }

    /** A fresh random key (for tests, or to write to a file). */
    public static PlatformKey random() {
        byte[] k = new byte[32];
        new SecureRandom().nextBytes(k);
        return new PlatformKey(k, "random");
    }

    /** The directory of the default key file: {@code $concord.home} or {@code ~/.concord}. */
    public static Path defaultDirectory() {
        String override = System.getProperty(HOME_PROPERTY);
        return override != null ? Path.of(override) : Path.of(System.getProperty("user.home"), ".concord");
    }

    /** The user's key in the default directory, created there on first use. */
    public static PlatformKey userDefault() {
        return loadOrCreate(defaultDirectory().resolve("platform.key"));
    }

    /**
     * Reads a key file, which must exist and be private.
     *
     * @throws IllegalStateException saying what is wrong with the file and how to fix it
     */
    public static PlatformKey load(Path file) {
        if (!Files.exists(file)) {
            throw new IllegalStateException("the platform key file " + file + " does not exist; copy "
                    + "platform.key from a host of the platform (it is in ~/.concord there), or leave the key "
                    + "unconfigured to create one for this user");
        }
        checkPrivate(file);
        try {
            String text = Files.readString(file, StandardCharsets.US_ASCII).trim();
            return new PlatformKey(parse(text, "the key file " + file), file.toString());
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the platform key file " + file + ": " + e.getMessage(), e);
        }
    }

    /**
     * Reads the key file, or creates it with a new random key (mode 0600) if it does not exist.
     * Agents started together agree on one key: the file appears whole and at once (a hard link to
     * a finished private file), and whoever comes second reads the first one's key.
     */
    public static PlatformKey loadOrCreate(Path file) {
        Path dir = file.toAbsolutePath().getParent();
        if (!Files.exists(file)) {
            try {
                createPrivateDirectories(dir);
                PlatformKey k = random();
                byte[] text = (HexFormat.of().formatHex(k.key) + "\n").getBytes(StandardCharsets.US_ASCII);
                Path tmp = Files.createTempFile(dir, ".platform", ".key");
                try {
                    restrict(tmp);
                    Files.write(tmp, text, StandardOpenOption.TRUNCATE_EXISTING);
                    publish(tmp, file);
                } finally {
                    Files.deleteIfExists(tmp);
                }
            } catch (IOException e) {
                throw new UncheckedIOException("cannot create the platform key file " + file + ": " + e.getMessage()
                        + "; make its directory writable or configure a key file", e);
            }
        }
        checkDirectory(dir);
        return load(file);
    }

    /**
     * Puts a finished file at its name unless one is there already. A link, unlike a rename,
     * never replaces an existing file, and the existence check and the link are one system call.
     */
    static void publish(Path finished, Path name) throws IOException {
        try {
            Files.createLink(name, finished);
        } catch (FileAlreadyExistsException raced) {
            // another agent created it first: use theirs
        } catch (UnsupportedOperationException noLinks) {
            try {
                Files.move(finished, name);
            } catch (FileAlreadyExistsException raced) {
                // another agent created it first: use theirs
            }
        }
    }

    /** Makes a file readable and writable by its owner only (where the file system has POSIX modes). */
    static void restrict(Path p) throws IOException {
        try {
            Files.setPosixFilePermissions(p, PosixFilePermissions.fromString("rw-------"));
        } catch (UnsupportedOperationException e) {
            // not a POSIX file system: rely on the user's directory permissions
        }
    }

    /** Creates a directory (and its parents) that only its owner may enter, if it is missing. */
    static void createPrivateDirectories(Path dir) throws IOException {
        if (Files.isDirectory(dir)) {
            return;
        }
        try {
            Files.createDirectories(dir, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx------")));
        } catch (UnsupportedOperationException e) {
            Files.createDirectories(dir);
        }
    }

    /**
     * Refuses a key or identity directory that another user owns or may write to: whoever can
     * write there can replace the platform key or an agent's identity.
     *
     * @throws IllegalStateException saying what is wrong and how to fix it
     */
    public static void checkDirectory(Path dir) {
        try {
            String me = System.getProperty("user.name");
            String owner = Files.getOwner(dir).getName();
            if (me != null && !me.equals(owner)) {
                throw new IllegalStateException("the key directory " + dir + " belongs to " + owner + ", not to "
                        + me + ", who runs this agent; use a directory of your own (-D" + HOME_PROPERTY + "=...)"
                        + " or: chown " + me + " " + dir);
            }
            Set<PosixFilePermission> perms = Files.getPosixFilePermissions(dir);
            if (perms.contains(PosixFilePermission.GROUP_WRITE) || perms.contains(PosixFilePermission.OTHERS_WRITE)) {
                throw new IllegalStateException("the key directory " + dir + " can be written by others ("
                        + PosixFilePermissions.toString(perms) + "): they could replace the keys in it; make it "
                        + "private: chmod 700 " + dir);
            }
        } catch (UnsupportedOperationException e) {
            // not a POSIX file system
        } catch (IOException e) {
            throw new UncheckedIOException("cannot check the owner and permissions of " + dir, e);
        }
    }

    /**
     * Refuses a key or identity file that others may read or write.
     *
     * @throws IllegalStateException saying how to make it private
     */
    static void checkPrivate(Path file) {
        try {
            Set<PosixFilePermission> perms = Files.getPosixFilePermissions(file);
            if (perms.contains(PosixFilePermission.GROUP_READ) || perms.contains(PosixFilePermission.OTHERS_READ)
                    || perms.contains(PosixFilePermission.GROUP_WRITE) || perms.contains(PosixFilePermission.OTHERS_WRITE)) {
                throw new IllegalStateException("the key file " + file + " can be read or written by others ("
                        + PosixFilePermissions.toString(perms) + "); make it private: chmod 600 " + file);
            }
        } catch (UnsupportedOperationException e) {
            // not a POSIX file system
        } catch (IOException e) {
            throw new UncheckedIOException("cannot check the permissions of " + file, e);
        }
    }

    private static byte[] parse(String hex, String where) {
        String h = hex.trim();
        if (h.length() != 64) {
            throw new IllegalStateException(where + " is not a platform key: expected 64 hex digits (256 bits), found "
                    + h.length() + " characters");
        }
        try {
            return HexFormat.of().parseHex(h);
        } catch (IllegalArgumentException e) {
            throw new IllegalStateException(where + " is not a platform key: " + e.getMessage(), e);
        }
    }

    /** The 32 key bytes (a copy). */
    public byte[] bytes() {
        return key.clone();
    }

    /** Where the key came from, for messages (never the key itself). */
    public String origin() {
        return origin;
    }

    @Override
    public String toString() {
        return "PlatformKey(" + origin + ")";
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof PlatformKey other && MessageDigest.isEqual(key, other.key);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(key);
    }

    /**
     * The key's id as frames carry it in their flags (bits 3-7, docs/wire-format.md): 5 bits of
     * HKDF-SHA256 of the key, info {@code concord key id v1}, shifted into place. No secret: it
     * tells another platform's frames from this one's before any tag is computed.
     */
    public int frameKeyBits() {
        return FrameSealer.keyBitsOf(bytes());
    }
}
