package io.concord.layers.security;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.util.Locale;

/**
 * Where agents' identities come from. An agent keeps its Ed25519 identity across restarts (so its
 * peers, who pinned it, still accept it) when the store is a directory; an ephemeral store makes a
 * new identity at every start (tests, throw-away agents).
 */
@FunctionalInterface
public interface IdentityStore {

    /** The identity of the named agent. */
    Identity identityFor(String agentName);

    /** A new identity at every start. */
    static IdentityStore ephemeral() {
        SecureRandom random = new SecureRandom();
        return name -> Identity.generate(random);
    }

    /** Identities kept as {@code <dir>/<agent name>.id} (the 32-byte seed, mode 0600). */
    static IdentityStore directory(Path dir) {
        SecureRandom random = new SecureRandom();
        return name -> {
            String file = name.toLowerCase(Locale.ROOT).replaceAll("[^a-z0-9@._-]", "_") + ".id";
            Path p = dir.resolve(file);
            try {
                if (Files.exists(p)) {
                    PlatformKey.checkDirectory(dir);
                    PlatformKey.checkPrivate(p);
                    byte[] seed = Files.readAllBytes(p);
                    if (seed.length != 32) {
                        throw new IllegalStateException("the identity file " + p + " is damaged (" + seed.length
                                + " bytes, expected 32); delete it to make a new identity, and tell its peers");
                    }
                    return Identity.fromSeed(seed, random);
                }
                PlatformKey.createPrivateDirectories(dir);
                PlatformKey.checkDirectory(dir);
                Identity id = Identity.generate(random);
                Path tmp = Files.createTempFile(dir, ".id", ".tmp");
                try {
                    PlatformKey.restrict(tmp);
                    Files.write(tmp, id.seed());
                    PlatformKey.publish(tmp, p);
                } finally {
                    Files.deleteIfExists(tmp);
                }
                // Two starts of one agent at once: both use the identity that won.
                return Identity.fromSeed(Files.readAllBytes(p), random);
            } catch (IOException e) {
                throw new UncheckedIOException("cannot read or write the identity " + p + ": " + e.getMessage(), e);
            }
        };
    }
}
