package io.concord.core.codec;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.time.ManualClock;
import org.junit.jupiter.api.Test;

import java.nio.charset.StandardCharsets;
import java.util.SplittableRandom;

import static org.junit.jupiter.api.Assertions.fail;

/**
 * Mutated and random inputs: a decoder either returns a whole message or throws
 * {@link AclParseException}; any other exception is a bug.
 */
class CodecFuzzTest {
    private static final int ITERATIONS = 60_000;

    @Test
    void binaryDecoderThrowsOnlyParseErrors() {
        fuzz(BinaryAclCodec.INSTANCE, 1);
    }

    @Test
    void stringDecoderThrowsOnlyParseErrors() {
        fuzz(new StringAclCodec(new ManualClock(), StandardCharsets.UTF_8), 2);
    }

    private static void fuzz(AclCodec codec, long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        for (int i = 0; i < ITERATIONS; i++) {
            byte[] input = mutate(codec.encode(new AclGenerator(r.nextLong()).message()), r);
            try {
                AclMessage m = codec.decode(input);
                if (m == null) {
                    fail("decode returned null for iteration " + i);
                }
                // Receivers may be built lazily: reading them must not fail once decoding succeeded.
                m.getReceivers().forEach(AID::name);
            } catch (AclParseException expected) {
                // fine: a clear error
            } catch (RuntimeException | StackOverflowError e) {
                fail("iteration " + i + ": " + e + " on input " + java.util.HexFormat.of().formatHex(input), e);
            }
        }
    }

    private static byte[] mutate(byte[] in, SplittableRandom r) {
        byte[] b = in.clone();
        switch (r.nextInt(5)) {
            case 0 -> {
                for (int k = 0, n = 1 + r.nextInt(4); k < n && b.length > 0; k++) {
                    b[r.nextInt(b.length)] ^= (byte) (1 << r.nextInt(8));
                }
            }
            case 1 -> b = java.util.Arrays.copyOf(b, r.nextInt(b.length + 1));
            case 2 -> {
                if (b.length > 0) {
                    b[r.nextInt(b.length)] = (byte) r.nextInt(256);
                }
            }
            case 3 -> {
                byte[] rnd = new byte[r.nextInt(64)];
                r.nextBytes(rnd);
                b = rnd;
            }
            default -> {
                if (b.length > 2) {
                    int at = r.nextInt(b.length);
                    byte[] c = new byte[b.length + 1];
                    System.arraycopy(b, 0, c, 0, at);
                    c[at] = (byte) "()\"#:\\ 9".charAt(r.nextInt(8));
                    System.arraycopy(b, at, c, at + 1, b.length - at);
                    b = c;
                }
            }
        }
        return b;
    }
}
