package io.concord.core.acl;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;

/**
 * An agent identifier (FIPA SC00023): a globally unique name {@code local@platform}, the ordered
 * transport addresses where the agent can be reached, optional resolvers (name services that know
 * it) and user-defined slots.
 *
 * <p>Immutable. Two AIDs are equal when their names are equal ignoring case, as in JADE; the
 * addresses are routing hints, not identity.
 */
public final class AID {
    private final String name;
    private String lowerName;
    private final List<String> addresses;
    private final List<AID> resolvers;
    private final Map<String, String> userDefined;

    /** An AID with a name and, optionally, its transport addresses in order of preference. */
    public AID(String name, String... addresses) {
        this(name, List.of(addresses), List.of(), Map.of());
    }

    /**
     * A full AID.
     *
     * @throws IllegalArgumentException if the name is empty
     */
    public AID(String name, List<String> addresses, List<AID> resolvers, Map<String, String> userDefined) {
        Objects.requireNonNull(name, "name");
        if (name.isEmpty()) {
            throw new IllegalArgumentException("an AID needs a non-empty name, such as alice@myplatform");
        }
        this.name = name;
        // List.copyOf returns an immutable list as it is; decoding hands over such lists.
        this.addresses = List.copyOf(addresses);
        this.resolvers = resolvers.isEmpty() ? List.of() : List.copyOf(resolvers);
        this.userDefined = userDefined.isEmpty() ? Map.of() : Collections.unmodifiableMap(new LinkedHashMap<>(userDefined));
        for (String k : this.userDefined.keySet()) {
            if (!AclMessage.isParameterName(k)) {
                throw new IllegalArgumentException("an AID slot name must be a word of letters, digits, '-', '_' "
                        + "or '.', starting with a letter; got '" + k + "'");
            }
        }
    }

    /** An AID named {@code local@platform}. */
    public static AID local(String local, String platform) {
        return new AID(local + "@" + platform);
    }

    /** The full name, {@code local@platform}. */
    public String name() {
        return name;
    }

    /** The part of the name before the last {@code @}, or the whole name if it has none. */
    public String localName() {
        int at = name.lastIndexOf('@');
        return at < 0 ? name : name.substring(0, at);
    }

    /** The part of the name after the last {@code @}, or the empty string if it has none. */
    public String platform() {
        int at = name.lastIndexOf('@');
        return at < 0 ? "" : name.substring(at + 1);
    }

    /** The transport addresses, most preferred first. */
    public List<String> addresses() {
        return addresses;
    }

    /** The resolvers (name services) that know this agent. */
    public List<AID> resolvers() {
        return resolvers;
    }

    /** User-defined slots, in the order they were given. */
    public Map<String, String> userDefined() {
        return userDefined;
    }

    /** This AID with the given addresses instead of its own. */
    public AID withAddresses(List<String> newAddresses) {
        return new AID(name, newAddresses, resolvers, userDefined);
    }

    /** The first address with the given scheme prefix (e.g. {@code "udp://"}), or {@code null}. */
    public String firstAddress(String schemePrefix) {
        for (String a : addresses) {
            if (a.regionMatches(true, 0, schemePrefix, 0, schemePrefix.length())) {
                return a;
            }
        }
        return null;
    }

    /** True if every slot, not only the name, is equal. */
    public boolean fullyEquals(AID other) {
        return other != null && name.equals(other.name) && addresses.equals(other.addresses)
                && resolvers.size() == other.resolvers.size() && userDefined.equals(other.userDefined)
                && resolversFullyEqual(other);
    }

    private boolean resolversFullyEqual(AID other) {
        for (int i = 0; i < resolvers.size(); i++) {
            if (!resolvers.get(i).fullyEquals(other.resolvers.get(i))) {
                return false;
            }
        }
        return true;
    }

    /** The name in lower case, computed when first needed (AIDs are compared far less than decoded). */
    private String lower() {
        String l = lowerName;
        if (l == null) {
            l = name.toLowerCase(Locale.ROOT);
            lowerName = l;
        }
        return l;
    }

    @Override
    public boolean equals(Object o) {
        return o == this || o instanceof AID other && (name.equals(other.name) || lower().equals(other.lower()));
    }

    @Override
    public int hashCode() {
        return lower().hashCode();
    }

    @Override
    public String toString() {
        return addresses.isEmpty() ? name : name + addresses;
    }
}
