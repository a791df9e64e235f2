package io.concord.layers.security;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class PlatformKeyTest {
    @TempDir
    Path dir;

    @Test
    void aMissingKeyIsCreatedOncePrivateAndThenShared() throws Exception {
        Path file = dir.resolve("sub").resolve("platform.key");
        PlatformKey first = PlatformKey.loadOrCreate(file);
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(file)));
        assertEquals(65, Files.size(file), "64 hex digits and a newline");
        assertEquals(first, PlatformKey.loadOrCreate(file), "the next agent reads the same key");
    }

    @Test
    void theDefaultKeyLivesInTheConfiguredHome() {
        String old = System.getProperty(PlatformKey.HOME_PROPERTY);
        System.setProperty(PlatformKey.HOME_PROPERTY, dir.toString());
        try {
            PlatformKey k = PlatformKey.userDefault();
            assertTrue(Files.exists(dir.resolve("platform.key")));
            assertEquals(k, PlatformKey.userDefault());
        } finally {
            if (old == null) {
                System.clearProperty(PlatformKey.HOME_PROPERTY);
            } else {
                System.setProperty(PlatformKey.HOME_PROPERTY, old);
            }
        }
    }

    @Test
    void aConfiguredFileThatDoesNotExistSaysWhereToGetOne() {
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> PlatformKey.load(dir.resolve("nope.key")));
        assertTrue(e.getMessage().contains("does not exist"), e.getMessage());
        assertTrue(e.getMessage().contains("copy"), e.getMessage());
    }

    @Test
    void aKeyFileOthersCanReadIsRefused() throws Exception {
        Path file = dir.resolve("open.key");
        Files.writeString(file, "00".repeat(32));
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-r--r--"));
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> PlatformKey.load(file));
        assertTrue(e.getMessage().contains("chmod 600"), e.getMessage());
    }

    @Test
    void aFileThatIsNotAKeyIsRefused() throws Exception {
        Path file = dir.resolve("bad.key");
        Files.writeString(file, "not a key");
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-------"));
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> PlatformKey.load(file));
        assertTrue(e.getMessage().contains("64 hex digits"), e.getMessage());
    }

    @Test
    void anIdentityDirectoryKeepsAnAgentsIdentityAcrossRestarts() {
        IdentityStore store = IdentityStore.directory(dir.resolve("ids"));
        byte[] first = store.identityFor("alice@p").signingPublicKey();
        byte[] again = store.identityFor("alice@p").signingPublicKey();
        assertEquals(java.util.HexFormat.of().formatHex(first), java.util.HexFormat.of().formatHex(again));
        assertTrue(!java.util.Arrays.equals(first, store.identityFor("bob@p").signingPublicKey()));
    }
}
