package jade.core;

import jade.util.leap.ArrayList;
import jade.util.leap.Iterator;
import jade.util.leap.Properties;

import java.util.Locale;

/**
 * JADE's agent identifier: a globally unique name {@code local@platform}, transport addresses,
 * resolvers and user-defined slots. Two AIDs are equal when their names are, ignoring case, as
 * JADE documents; addresses do not count.
 *
 * <p>{@code new AID("alice", AID.ISLOCALNAME)} completes the name with the platform's name, the
 * one the running {@link Runtime}'s container took (its {@code Profile.PLATFORM_ID}).
 */
public class AID implements jade.util.leap.Comparable, jade.util.leap.Serializable {
    private static final long serialVersionUID = 1L;

    /** The separator between local name and platform. */
    public static final char HAP_SEPARATOR = '@';
    /** The name given is a full {@code local@platform} name. */
    public static final boolean ISGUID = true;
    /** The name given is a local name, to be completed with the platform's. */
    public static final boolean ISLOCALNAME = false;
    /** The user-defined slot JADE uses for the agent's class name. */
    public static final String AGENT_CLASSNAME = "JADE-agent-classname";

    /** The platform's name, set when a container starts in this JVM. */
    static volatile String platformId = "JADE";

    private String name;
    private final ArrayList addresses = new ArrayList();
    private final ArrayList resolvers = new ArrayList();
    private final Properties userDefSlots = new Properties();

    /** An AID with no name yet. */
    public AID() {
    }

    /** An AID with a full name ({@code local@platform}). */
    public AID(String guid) {
        this(guid, ISGUID);
    }

    /**
     * An AID from a full name ({@link #ISGUID}) or a local name ({@link #ISLOCALNAME}), completed
     * with this platform's name.
     */
    public AID(String name, boolean isGUID) {
        if (isGUID) {
            setName(name);
        } else {
            setLocalName(name);
        }
    }

    /** Sets the full name (trimmed). */
    public void setName(String n) {
        this.name = n == null ? null : n.trim();
    }

    /** Sets the name from a local name: {@code local@platform}, with this platform's name. */
    public void setLocalName(String n) {
        if (n == null) {
            this.name = null;
            return;
        }
        String local = n.trim();
        this.name = createGUID(local, platformId);
    }

    /** The full name of a local name on a platform. */
    public static String createGUID(String localName, String platformName) {
        return localName.trim() + HAP_SEPARATOR + platformName;
    }

    /** The full name, {@code local@platform}. */
    public String getName() {
        return name;
    }

    /** The part before the last {@code @}, or the whole name if it has none. */
    public String getLocalName() {
        if (name == null) {
            return null;
        }
        int at = name.lastIndexOf(HAP_SEPARATOR);
        return at < 0 ? name : name.substring(0, at);
    }

    /** The part after the last {@code @}: the platform (home agent platform). */
    public String getHap() {
        if (name == null) {
            return null;
        }
        int at = name.lastIndexOf(HAP_SEPARATOR);
        return at < 0 ? name : name.substring(at + 1);
    }

    /** Adds a transport address (kept once, in order). */
    public void addAddresses(String url) {
        if (url != null && !addresses.contains(url)) {
            addresses.add(url);
        }
    }

    public boolean removeAddresses(String url) {
        return addresses.remove(url);
    }

    public void clearAllAddresses() {
        addresses.clear();
    }

    public Iterator getAllAddresses() {
        return addresses.iterator();
    }

    public String[] getAddressesArray() {
        Object[] a = addresses.toArray();
        String[] r = new String[a.length];
        for (int i = 0; i < a.length; i++) {
            r[i] = (String) a[i];
        }
        return r;
    }

    public void addResolvers(AID aid) {
        if (aid != null && !resolvers.contains(aid)) {
            resolvers.add(aid);
        }
    }

    public boolean removeResolvers(AID aid) {
        return resolvers.remove(aid);
    }

    public void clearAllResolvers() {
        resolvers.clear();
    }

    public Iterator getAllResolvers() {
        return resolvers.iterator();
    }

    public AID[] getResolversArray() {
        Object[] a = resolvers.toArray();
        AID[] r = new AID[a.length];
        for (int i = 0; i < a.length; i++) {
            r[i] = (AID) a[i];
        }
        return r;
    }

    public void addUserDefinedSlot(String key, String value) {
        userDefSlots.setProperty(key, value);
    }

    public boolean removeUserDefinedSlot(String key) {
        return userDefSlots.remove(key) != null;
    }

    public Properties getAllUserDefinedSlot() {
        return userDefSlots;
    }

    /** The AID in FIPA SL: {@code ( agent-identifier :name n :addresses (sequence ...))}. */
    @Override
    public String toString() {
        // JADE 4.3's layout, space for space (seen from its output)
        StringBuilder b = new StringBuilder("( agent-identifier ");
        if (name != null) {
            b.append(":name ").append(name).append(' ');
        }
        if (!addresses.isEmpty()) {
            b.append(" :addresses (sequence ");
            for (Object a : addresses.toArray()) {
                b.append(a).append(' ');
            }
            b.append(")");
        }
        if (!resolvers.isEmpty()) {
            b.append(" :resolvers (sequence ");
            for (Object r : resolvers.toArray()) {
                b.append(r).append(' ');
            }
            b.append(")");
        }
        for (java.util.Enumeration<Object> e = userDefSlots.keys(); e.hasMoreElements(); ) {
            String k = String.valueOf(e.nextElement());
            b.append(" :X-").append(k).append(' ').append(userDefSlots.getProperty(k)).append(' ');
        }
        return b.append(")").toString();
    }

    @Override
    public synchronized Object clone() {
        AID c = new AID(name, ISGUID);
        for (Object a : addresses.toArray()) {
            c.addAddresses((String) a);
        }
        for (Object r : resolvers.toArray()) {
            c.addResolvers((AID) ((AID) r).clone());
        }
        c.userDefSlots.putAll(userDefSlots);
        return c;
    }

    /** Equal names, ignoring case. */
    @Override
    public boolean equals(Object o) {
        if (!(o instanceof AID other)) {
            return false;
        }
        return name == null ? other.name == null : name.equalsIgnoreCase(other.name);
    }

    /** Orders by name, ignoring case. */
    @Override
    public int compareTo(Object o) {
        AID other = (AID) o;
        return lower(name).compareTo(lower(other.name));
    }

    @Override
    public int hashCode() {
        return lower(name).hashCode();
    }

    private static String lower(String s) {
        return s == null ? "" : s.toLowerCase(Locale.ROOT);
    }
}
