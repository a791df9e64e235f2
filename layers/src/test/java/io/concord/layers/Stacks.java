package io.concord.layers;

import io.concord.core.layer.Layer;
import io.concord.layers.security.IdentityStore;
import io.concord.layers.security.PlatformKey;

import java.util.List;
import java.util.function.Supplier;

/** Stacks for tests: a fixed platform key and fresh identities, nothing written to the home directory. */
public final class Stacks {
    /** The platform key of the tests' platform. */
    public static final PlatformKey KEY = PlatformKey.ofHex("000102030405060708090a0b0c0d0e0f101112131415161718191a1b1c1d1e1f");

    private Stacks() {
    }

    public static SafetyStack.Builder builder(Profile profile) {
        return SafetyStack.builder().profile(profile).platformKey(KEY).identities(IdentityStore.ephemeral());
    }

    public static Supplier<List<Layer>> of(Profile profile) {
        return builder(profile).build();
    }
}
