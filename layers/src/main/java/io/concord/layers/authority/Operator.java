package io.concord.layers.authority;

import java.util.HexFormat;
import java.util.Objects;

/** An operator as a ward knows them: a name and the Ed25519 public key their orders verify under. */
public record Operator(String name, byte[] publicKey) {
    public Operator {
        Objects.requireNonNull(name, "name");
        if (!SignedOrder.WORD.matcher(name).matches()) {
            throw new IllegalArgumentException("an operator's name is 1 to 64 letters, digits, spaces or . _ - @ :, got '" + name + "'");
        }
        if (publicKey == null || publicKey.length != 32) {
            throw new IllegalArgumentException("an operator's public key is 32 bytes (Ed25519), got "
                    + (publicKey == null ? "none" : publicKey.length));
        }
        publicKey = publicKey.clone();
    }

    @Override
    public byte[] publicKey() {
        return publicKey.clone();
    }

    /** The line a ward's operators file holds for this operator: {@code operator <hex public key> <name>}. */
    public String line() {
        return "operator " + HexFormat.of().formatHex(publicKey) + " " + name;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Operator p && p.name.equals(name) && java.util.Arrays.equals(p.publicKey, publicKey);
    }

    @Override
    public int hashCode() {
        return name.hashCode() * 31 + java.util.Arrays.hashCode(publicKey);
    }

    @Override
    public String toString() {
        return name;
    }
}
