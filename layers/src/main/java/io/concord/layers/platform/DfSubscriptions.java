package io.concord.layers.platform;

import io.concord.core.acl.AclMessage;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.BiConsumer;
import java.util.function.Function;
import java.util.function.Predicate;

/**
 * The DF's subscriptions (FIPA's subscribe protocol): who asked to be told of the agents whose
 * services match a template, and what each was told last. The container holds them; after each
 * change of its list it works out, per subscription, the entries that came to match or changed
 * (told with their services) and those that stopped matching (told with no services, as JADE's DF
 * tells a deregistration). A subscription lives while its subscriber is listed, until it cancels.
 * Held by the container only: a new container after a failover starts with none.
 */
final class DfSubscriptions {

    private static final class Subscription {
        final AclMessage request;
        final ServiceDescription template;
        final Map<String, AgentEntry> told = new HashMap<>();

        Subscription(AclMessage request, ServiceDescription template) {
            this.request = request;
            this.template = template;
        }

        String subscriber() {
            return request.getSender().name();
        }
    }

    private final List<Subscription> subscriptions = new ArrayList<>();

    /**
     * Adds a subscription (replacing one of the same subscriber and conversation) and returns the
     * entries that match now, which the subscriber is told at once (nothing if none).
     */
    List<AgentEntry> add(AclMessage request, ServiceDescription template,
                         Function<ServiceDescription, List<AgentEntry>> search) {
        cancel(request.getSender().name(), request.getConversationId());
        Subscription s = new Subscription(request, template);
        List<AgentEntry> now = search.apply(template);
        for (AgentEntry e : now) {
            s.told.put(e.name(), e);
        }
        subscriptions.add(s);
        return now;
    }

    /** Ends the subscriptions of this subscriber in this conversation; true if there was one. */
    boolean cancel(String subscriber, String conversationId) {
        return subscriptions.removeIf(s -> s.subscriber().equals(subscriber)
                && Objects.equals(s.request.getConversationId(), conversationId));
    }

    /** How many subscriptions are held. */
    int size() {
        return subscriptions.size();
    }

    /**
     * After a change of the list: drops the subscriptions of agents no longer listed, and hands
     * each remaining subscription's request and what changed for it (if anything) to {@code notify}.
     */
    void changed(Predicate<String> listed, Function<ServiceDescription, List<AgentEntry>> search,
                 BiConsumer<AclMessage, List<AgentEntry>> notify) {
        for (Iterator<Subscription> it = subscriptions.iterator(); it.hasNext(); ) {
            Subscription s = it.next();
            if (!listed.test(s.subscriber())) {
                it.remove();
                continue;
            }
            Map<String, AgentEntry> now = new LinkedHashMap<>();
            for (AgentEntry e : search.apply(s.template)) {
                now.put(e.name(), e);
            }
            List<AgentEntry> news = new ArrayList<>();
            for (AgentEntry e : now.values()) {
                AgentEntry was = s.told.get(e.name());
                if (was == null || !was.services().equals(e.services())) {
                    news.add(e);
                }
            }
            for (AgentEntry was : s.told.values()) {
                if (!now.containsKey(was.name())) {
                    news.add(was.withServices(List.of()));
                }
            }
            if (!news.isEmpty()) {
                s.told.clear();
                s.told.putAll(now);
                notify.accept(s.request, news);
            }
        }
    }
}
