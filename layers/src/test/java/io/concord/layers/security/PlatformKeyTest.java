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
    void agentsStartedTogetherAllEndWithOneKey() throws Exception {
        int rounds = 60;
        int agents = 8;
        java.util.concurrent.ExecutorService pool = java.util.concurrent.Executors.newFixedThreadPool(agents);
        try {
            for (int r = 0; r < rounds; r++) {
                Path file = dir.resolve("race" + r).resolve("platform.key");
                java.util.concurrent.CyclicBarrier start = new java.util.concurrent.CyclicBarrier(agents);
                java.util.List<java.util.concurrent.Future<PlatformKey>> keys = new java.util.ArrayList<>();
                for (int a = 0; a < agents; a++) {
                    keys.add(pool.submit(() -> {
                        start.await();
                        return PlatformKey.loadOrCreate(file);
                    }));
                }
                java.util.Set<PlatformKey> distinct = new java.util.HashSet<>();
                for (java.util.concurrent.Future<PlatformKey> k : keys) {
                    distinct.add(k.get());
                }
                distinct.add(PlatformKey.load(file));
                assertEquals(1, distinct.size(), "round " + r + ": agents started together hold different keys");
            }
        } finally {
            pool.shutdownNow();
        }
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

    @Test
    void aKeyDirectoryOthersCanWriteIsRefused() throws Exception {
        Path home = dir.resolve("home");
        PlatformKey.loadOrCreate(home.resolve("platform.key"));
        assertEquals("rwx------", PosixFilePermissions.toString(Files.getPosixFilePermissions(home)),
                "a directory it creates is private");
        Files.setPosixFilePermissions(home, PosixFilePermissions.fromString("rwxrwxrwx"));
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> PlatformKey.loadOrCreate(home.resolve("platform.key")));
        assertTrue(e.getMessage().contains("chmod 700"), e.getMessage());
        IllegalStateException id = assertThrows(IllegalStateException.class,
                () -> IdentityStore.directory(home).identityFor("alice@p"));
        assertTrue(id.getMessage().contains("chmod 700"), id.getMessage());
    }

    @Test
    void aKeyDirectoryOfAnotherUserIsRefused() throws Exception {
        Path home = Files.createDirectories(dir.resolve("theirs"));
        java.nio.file.attribute.UserPrincipal nobody;
        try {
            nobody = home.getFileSystem().getUserPrincipalLookupService().lookupPrincipalByName("nobody");
            Files.setOwner(home, nobody);
        } catch (java.io.IOException notRoot) {
            org.junit.jupiter.api.Assumptions.abort("only root can give a directory to nobody: " + notRoot);
            return;
        }
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> PlatformKey.loadOrCreate(home.resolve("platform.key")));
        assertTrue(e.getMessage().contains("belongs to nobody"), e.getMessage());
    }

    @Test
    void anIdentityFileOthersCanReadIsRefused() throws Exception {
        Path ids = dir.resolve("ids");
        IdentityStore.directory(ids).identityFor("alice@p");
        Path file = ids.resolve("alice@p.id");
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(file)));
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-r--r--"));
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> IdentityStore.directory(ids).identityFor("alice@p"));
        assertTrue(e.getMessage().contains("chmod 600"), e.getMessage());
    }

    @Test
    void oneAgentStartedTwiceAtOnceHasOneIdentity() throws Exception {
        Path ids = dir.resolve("twice");
        java.util.concurrent.ExecutorService pool = java.util.concurrent.Executors.newFixedThreadPool(4);
        try {
            for (int r = 0; r < 40; r++) {
                String name = "agent" + r + "@p";
                java.util.concurrent.CyclicBarrier start = new java.util.concurrent.CyclicBarrier(4);
                java.util.Set<String> keys = java.util.concurrent.ConcurrentHashMap.newKeySet();
                java.util.List<java.util.concurrent.Future<?>> done = new java.util.ArrayList<>();
                for (int a = 0; a < 4; a++) {
                    done.add(pool.submit(() -> {
                        start.await();
                        keys.add(java.util.HexFormat.of().formatHex(IdentityStore.directory(ids).identityFor(name).signingPublicKey()));
                        return null;
                    }));
                }
                for (java.util.concurrent.Future<?> f : done) {
                    f.get();
                }
                assertEquals(1, keys.size(), name + " started four times at once has " + keys.size() + " identities");
            }
        } finally {
            pool.shutdownNow();
        }
    }
}
