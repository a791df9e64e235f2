package io.concord.core.agent;

import org.junit.jupiter.api.Test;

import java.util.Arrays;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

/**
 * A runtime's secrets: nobody can guess them on a runtime that faces a network (a SecureRandom),
 * and a simulation's (a runtime given a seed) replay.
 */
class SecretBytesTest {

    private static byte[] secret(AgentRuntime rt) {
        byte[] b = new byte[16];
        rt.secretBytes(b);
        return b;
    }

    @Test
    void twoRuntimesWithNoSeedShareNoSecretAndTwoWithOneSeedReplay() {
        try (AgentRuntime a = AgentRuntime.builder().build(); AgentRuntime b = AgentRuntime.builder().build()) {
            assertFalse(Arrays.equals(secret(a), secret(b)), "a SecureRandom's, not a seed's");
        }
        try (AgentRuntime a = AgentRuntime.builder().seed(7).build(); AgentRuntime b = AgentRuntime.builder().seed(7).build()) {
            assertArrayEquals(secret(a), secret(b), "the seed's: a simulation replays");
        }
    }
}
